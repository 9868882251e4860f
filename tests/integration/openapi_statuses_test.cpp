// The statuses api/openapi.yaml gives every operation, against the real server: each operation behind
// the token documents 401 and answers it without one; each operation documents 503 `not_ready` and
// answers it while the server loads at start, except the probes getHealth and getMetrics, which answer
// 200 throughout. Every
// operation is called as the document names it (its path parameters filled in).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

struct Operation {
  std::string method;  // upper case
  std::string path;    // with its parameters filled in
  std::string id;
  YAML::Node node;
  bool secured = true;
};

std::vector<Operation> operations() {
  const YAML::Node doc = YAML::LoadFile(LIGHTPROBE_OPENAPI);
  std::vector<Operation> out;
  for (const auto& path : doc["paths"]) {
    const std::string filled =
        std::regex_replace(path.first.as<std::string>(), std::regex(R"(\{[^}]+\})"), "x");
    for (const char* method : {"get", "post", "put", "delete", "patch"}) {
      const YAML::Node op = path.second[method];
      if (!op) continue;
      Operation o{method, filled, op["operationId"].as<std::string>(), op};
      for (char& ch : o.method) ch = char(std::toupper(ch));
      o.secured = !(op["security"] && op["security"].size() == 0);
      out.push_back(o);
    }
  }
  return out;
}

// The resolved description of an operation's response, "" if it has none.
std::string response_text(const YAML::Node& op, const std::string& status) {
  const YAML::Node r = op["responses"][status];
  if (!r) return "";
  if (r["$ref"]) {
    const std::string name =
        r["$ref"].as<std::string>().substr(std::string("#/components/responses/").size());
    return YAML::LoadFile(LIGHTPROBE_OPENAPI)["components"]["responses"][name]["description"]
        .as<std::string>();
  }
  return r["description"].as<std::string>();
}

test::Reply call(const test::ServerProcess& s, const Operation& o) {
  auto c = s.client();
  if (o.method == "GET") return test::reply(c->Get(o.path.c_str()));
  if (o.method == "DELETE") return test::reply(c->Delete(o.path.c_str()));
  if (o.method == "PUT") return test::reply(c->Put(o.path.c_str(), "{}", "application/json"));
  return test::reply(c->Post(o.path.c_str(), "{}", "application/json"));
}

TEST(OpenApiStatuses, EveryOperationBehindTheTokenDocumentsAndAnswers401) {
  test::TempDir dir;
  const auto token = dir.path() / "token";
  std::ofstream(token) << "0123456789abcdef0123456789abcdef\n";
  test::ServerProcess s({"--auth-token-file", token.string()});
  const auto ops = operations();
  ASSERT_GT(ops.size(), 30u);
  for (const Operation& o : ops) {
    SCOPED_TRACE(o.method + " " + o.path + " (" + o.id + ")");
    const test::Reply r = call(s, o);
    if (o.secured) {
      EXPECT_EQ(r.status, 401) << r.body;
      EXPECT_NE(response_text(o.node, "401").find("unauthorized"), std::string::npos);
    } else {
      EXPECT_NE(r.status, 401);
      EXPECT_FALSE(o.node["responses"]["401"]);
    }
  }
}

TEST(OpenApiStatuses, EveryOperationButTheProbesDocumentsAndAnswersNotReadyAtStart) {
  test::TempDir dir;
  const auto fifo = dir.path() / "slow.pfm";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::ServerProcess s({"--load", "slow=" + fifo.string()}, {}, test::StartUntil::Listening);
  for (const Operation& o : operations()) {
    SCOPED_TRACE(o.method + " " + o.path + " (" + o.id + ")");
    const test::Reply r = call(s, o);
    if (o.id == "getHealth" || o.id == "getMetrics") {
      EXPECT_EQ(r.status, 200);
      EXPECT_EQ(response_text(o.node, "503").find("not_ready"), std::string::npos);
      continue;
    }
    EXPECT_EQ(r.status, 503) << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "not_ready") << r.body;
    EXPECT_NE(response_text(o.node, "503").find("not_ready"), std::string::npos)
        << response_text(o.node, "503");
  }
}

}  // namespace
}  // namespace lp

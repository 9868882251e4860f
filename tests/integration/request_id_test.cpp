// Every response of the real server carries a request id in X-Request-Id: the client's own when it is
// safe, else a new one; an error's body and the access log line carry the same id, the transport's own
// refusals included.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "support/http_reply.hpp"
#include "support/raw_connection.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

const std::regex kNewId("[0-9a-f]{16}");

Reply get(const test::ServerProcess& s, const std::string& path, const httplib::Headers& headers = {}) {
  return test::reply(s.client()->Get(path.c_str(), headers));
}

TEST(RequestIds, AClientsSafeIdIsKeptAndAnsweredInTheErrorBody) {
  const auto& s = test::default_server();
  const std::string id = "3fa85f64-5717-4562-b3fc-2c963f66afa6";
  const Reply ok = get(s, "/api/v1/health", {{"X-Request-Id", id}});
  EXPECT_EQ(ok.status, 200);
  EXPECT_EQ(ok.header("X-Request-Id"), id);
  const Reply missing = get(s, "/api/v1/envmaps/absent", {{"X-Request-Id", id}});
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.header("X-Request-Id"), id);
  EXPECT_EQ(missing.body_json()["error"]["request_id"], id) << missing.body;
  EXPECT_EQ(missing.body_json()["error"]["code"], "not_found");
}

TEST(RequestIds, UnsafeOrMissingIdsAreReplacedByNewOnes) {
  const auto& s = test::default_server();
  std::set<std::string> seen;
  for (const std::string& given : {std::string(), std::string(129, 'a'), std::string("a b"),
                                   std::string("<script>"), std::string("caf\xc3\xa9")}) {
    const Reply r = given.empty() ? get(s, "/api/v1/envmaps/absent")
                                  : get(s, "/api/v1/envmaps/absent", {{"X-Request-Id", given}});
    const std::string id = r.header("X-Request-Id");
    EXPECT_TRUE(std::regex_match(id, kNewId)) << "'" << given << "' -> '" << id << "'";
    EXPECT_EQ(r.body_json()["error"]["request_id"], id);
    seen.insert(id);
  }
  EXPECT_EQ(seen.size(), 5u);
}

TEST(RequestIds, TheTransportsOwnRefusalsHaveOne) {
  const auto& s = test::default_server();
  test::RawConnection c(s.port());
  c.send("GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: " + std::string(9000, 'x') + "\r\n\r\n");
  const auto r = c.read_response();
  EXPECT_EQ(r.status, 431) << r.head;
  const std::string id = json::parse(r.body)["error"]["request_id"];
  EXPECT_TRUE(std::regex_match(id, kNewId)) << r.body;
  EXPECT_TRUE(r.has_header("X-Request-Id: " + id)) << r.head;
}

TEST(RequestIds, TheAccessLogLineHasTheId) {
  test::ServerProcess s;
  const Reply r = get(s, "/api/v1/envmaps/absent", {{"X-Request-Id", "trace-me.42"}});
  EXPECT_EQ(r.status, 404);
  s.send_signal(SIGTERM);
  ASSERT_EQ(s.wait_exit(std::chrono::seconds(30)), 0);
  EXPECT_TRUE(std::regex_search(
      s.log(), std::regex(R"(info GET /api/v1/envmaps/absent 404 [0-9.]+ ms id=trace-me\.42\n)")))
      << s.log();
}

}  // namespace
}  // namespace lp

// Every JSON endpoint of the real server refuses a body nested deeper than kMaxJsonDepth with a 400 that
// names the limit, and keeps serving (a 100,000-level value once overflowed the stack and killed the
// server); so are state records at start. Error messages quote client values only as short excerpts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "api/excerpt.hpp"
#include "api/params.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using test::Reply;

Reply post_json(const std::string& path, const std::string& body) {
  return test::reply(test::default_server().client()->Post(path.c_str(), body, "application/json"));
}
Reply get(const std::string& path) {
  return test::reply(test::default_server().client()->Get(path.c_str()));
}

std::string arrays(int depth) {
  return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
}

const char* const kJsonEndpoints[] = {"/api/v1/envmaps", "/api/v1/envmaps/default/samples",
                                      "/api/v1/envmaps/default/median-cut", "/api/v1/renders"};

void expect_too_deep(const std::string& path, const std::string& body) {
  const Reply r = post_json(path, body);
  ASSERT_EQ(r.status, 400) << path << ": " << r.body.substr(0, 300);
  EXPECT_EQ(r.body_json()["error"]["code"], "json_too_deep") << path;
  EXPECT_NE(r.body.find("limit of " + std::to_string(api::kMaxJsonDepth) + " levels"), std::string::npos)
      << r.body;
  EXPECT_LT(r.body.size(), 200u) << path;
}

TEST(JsonLimits, HundredThousandLevelsGet400FromEveryJsonEndpointAndTheServerStaysUp) {
  const std::string field = R"({"count":)" + arrays(100'000) + "}";  // about 200 KB
  std::string objects;
  for (int i = 0; i < 100'000; ++i) objects += R"({"a":)";
  objects += '0';
  objects.append(100'000, '}');
  for (const char* path : kJsonEndpoints) {
    expect_too_deep(path, field);
    expect_too_deep(path, objects);
    expect_too_deep(path, arrays(100'000));
  }
  ASSERT_TRUE(test::default_server().alive());
  EXPECT_EQ(get("/api/v1/health").status, 200);
  EXPECT_EQ(post_json("/api/v1/envmaps/default/samples", R"({"count":4})").status, 200);
}

TEST(JsonLimits, TheLimitItselfIsParsed) {
  // The body object is the first level; its field adds kMaxJsonDepth - 1 more: parsed, then refused as a
  // wrong type (not as too deep).
  const Reply at_limit =
      post_json("/api/v1/envmaps/default/samples", R"({"count":)" + arrays(api::kMaxJsonDepth - 1) + "}");
  EXPECT_EQ(at_limit.status, 400);
  EXPECT_EQ(at_limit.body_json()["error"]["message"],
            "field 'count': must be an integer, got an array of 1 item");
  expect_too_deep("/api/v1/envmaps/default/samples", R"({"count":)" + arrays(api::kMaxJsonDepth) + "}");
}

TEST(JsonLimits, MessagesQuoteOnlyAnExcerptOfClientValues) {
  const std::string huge(100'000, 'x');
  const std::string quoted = huge.substr(0, api::kExcerptBytes) + "...";
  const auto message = [](const Reply& r) { return r.body_json()["error"]["message"].get<std::string>(); };

  const Reply value = post_json("/api/v1/envmaps/default/samples", R"({"count":")" + huge + R"("})");
  EXPECT_EQ(message(value), "field 'count': must be an integer, got \"" + quoted + "\"");
  const Reply key = post_json("/api/v1/envmaps/default/median-cut", R"({")" + huge + R"(":1})");
  EXPECT_EQ(message(key).find("field '" + quoted + "': unknown field"), 0u) << message(key);
  const Reply map = post_json("/api/v1/renders", R"({"envmap":")" + huge + R"("})");
  EXPECT_EQ(map.status, 400);
  EXPECT_EQ(message(map), "field 'envmap': no environment map '" + quoted + "' is loaded");
  const Reply id = get("/api/v1/envmaps/" + huge.substr(0, 4000));
  EXPECT_EQ(id.status, 404);
  EXPECT_EQ(message(id), "no environment map with id '" + quoted + "'");
  const Reply query = get("/api/v1/fresnel?eta_i=1&eta_t=" + huge.substr(0, 4000));
  EXPECT_EQ(message(query), "field 'eta_t': '" + quoted + "' is not a finite number");
}

TEST(JsonLimits, AStateRecordNestedTooDeepIsSkippedAndTheServerStarts) {
  test::TempDir state;
  std::filesystem::create_directories(state.path() / "renders");
  std::ofstream(state.path() / "renders" / "0123456789abcdef.json")
      << R"({"version":1,"id":"0123456789abcdef","request":)" << arrays(100'000) << "}";
  test::ServerProcess restarted({"--state-dir", state.path().string()});
  EXPECT_EQ(test::reply(restarted.client()->Get("/api/v1/health")).status, 200);
  EXPECT_EQ(test::reply(restarted.client()->Get("/api/v1/renders")).body_json()["renders"].size(), 0u);
  const std::string skipped = "the record nests arrays and objects deeper than the limit of " +
                              std::to_string(api::kMaxJsonDepth) + " levels";
  EXPECT_TRUE(restarted.wait_log(skipped)) << restarted.log();
}

TEST(JsonLimits, TheApiDocumentStatesTheLimits) {
  const std::string doc = get("/api/v1/openapi.yaml").body;
  EXPECT_NE(doc.find("nest at most " + std::to_string(api::kMaxJsonDepth) + " levels"), std::string::npos);
  EXPECT_NE(doc.find("at most the first " + std::to_string(api::kExcerptBytes) + " bytes"),
            std::string::npos);
}

}  // namespace
}  // namespace lp

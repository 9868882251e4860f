// Request bodies nested far deeper than kMaxJsonDepth get a 400 from every JSON endpoint of the real
// server, which keeps answering (a 100,000-level value once overflowed the stack while being quoted in
// an error message), and error messages quote client values only in short excerpts.
#include <gtest/gtest.h>

#include <string>

#include "api/params.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using test::Reply;

std::string nested_array(int depth) {
  return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
}

test::ServerProcess& server() {
  static test::ServerProcess process;
  return process;
}

Reply post_json(const std::string& path, const std::string& body) {
  return test::reply(server().client()->Post(path.c_str(), body, "application/json"));
}

const char* const kJsonEndpoints[] = {"/api/v1/envmaps", "/api/v1/envmaps/default/samples",
                                      "/api/v1/envmaps/default/median-cut", "/api/v1/renders"};

TEST(JsonLimits, HundredThousandLevelsGet400FromEveryJsonEndpoint) {
  const std::string body = R"({"count": )" + nested_array(100'000) + "}";
  for (const char* path : kJsonEndpoints) {
    const Reply r = post_json(path, body);
    EXPECT_EQ(r.status, 400) << path << ": " << r.body.substr(0, 200);
    EXPECT_EQ(r.body_json()["error"]["code"], "json_too_deep") << path;
    EXPECT_LT(r.body.size(), 300u) << path;
  }
  EXPECT_TRUE(server().alive());
  EXPECT_EQ(test::reply(server().client()->Get("/api/v1/health")).status, 200);
  EXPECT_EQ(post_json("/api/v1/envmaps/default/samples", R"({"count": 4})").status, 200);
}

TEST(JsonLimits, DepthLimitIsExact) {
  // The body object is level 1: a field holding kMaxJsonDepth - 1 nested arrays reaches the limit.
  const std::string at_limit = R"({"count": )" + nested_array(api::kMaxJsonDepth - 1) + "}";
  const Reply ok = post_json("/api/v1/envmaps/default/samples", at_limit);
  EXPECT_EQ(ok.status, 400);
  EXPECT_EQ(ok.body_json()["error"]["code"], "invalid_field") << ok.body;
  const std::string over = R"({"count": )" + nested_array(api::kMaxJsonDepth) + "}";
  EXPECT_EQ(post_json("/api/v1/envmaps/default/samples", over).body_json()["error"]["code"], "json_too_deep");
}

TEST(JsonLimits, MessagesQuoteOnlyAnExcerptOfLongValues) {
  const std::string long_text(200'000, 'x');
  const Reply typed = post_json("/api/v1/envmaps/default/samples", R"({"count": ")" + long_text + R"("})");
  EXPECT_EQ(typed.status, 400);
  EXPECT_LT(typed.body.size(), 300u) << typed.body.substr(0, 300);
  const Reply key = post_json("/api/v1/envmaps/default/samples", R"({")" + long_text + R"(": 1})");
  EXPECT_EQ(key.status, 400);
  EXPECT_LT(key.body.size(), 600u) << key.body.substr(0, 300);
  const Reply array =
      post_json("/api/v1/envmaps/default/samples", R"({"count": [)" + std::string("1,") + "2]}");
  EXPECT_NE(array.body.find("an array of 2 items"), std::string::npos) << array.body;
}

TEST(JsonLimits, TheDocumentStatesTheLimit) {
  const Reply doc = test::reply(server().client()->Get("/api/v1/openapi.yaml"));
  const std::string stated = "nest at most " + std::to_string(api::kMaxJsonDepth) + " levels";
  EXPECT_NE(doc.body.find(stated), std::string::npos);
}

}  // namespace
}  // namespace lp

// What a web browser may ask: Host names this server (DNS-rebinding defence), state-changing requests
// from another origin are refused unless --cors-origin lists it, and JSON bodies must say they are JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

const std::string kRender =
    R"({"envmap":"default","scene":{"preset":"sphere"},"width":16,"height":16,"spp":1})";

Reply post(const test::ServerProcess& s, const std::string& path, const std::string& body,
           const std::string& type, const httplib::Headers& headers = {}) {
  return test::reply(s.client()->Post(path.c_str(), headers, body, type.c_str()));
}

size_t render_count(const test::ServerProcess& s) {
  return test::reply(s.client()->Get("/api/v1/renders")).body_json()["renders"].size();
}

void expect_error(const Reply& r, int status, const std::string& code) {
  EXPECT_EQ(r.status, status) << r.body;
  if (r.status == status) {
    EXPECT_EQ(r.body_json()["error"]["code"], code) << r.body;
  }
}

TEST(BrowserPolicy, CrossOriginPostsAreRefusedAndQueueNothing) {
  const auto& s = test::default_server();
  const size_t before = render_count(s);
  expect_error(post(s, "/api/v1/renders", kRender, "text/plain", {{"Origin", "http://evil.example"}}), 403,
               "origin_not_allowed");
  expect_error(post(s, "/api/v1/renders", kRender, "application/json", {{"Origin", "http://evil.example"}}),
               403, "origin_not_allowed");
  expect_error(
      test::reply(s.client()->Delete("/api/v1/envmaps/default", {{"Origin", "http://evil.example"}})), 403,
      "origin_not_allowed");
  EXPECT_EQ(render_count(s), before);
  EXPECT_EQ(test::reply(s.client()->Get("/api/v1/envmaps/default")).status, 200);
  // Reading is allowed from anywhere (the browser keeps the answer from the page without CORS headers).
  EXPECT_EQ(test::reply(s.client()->Get("/api/v1/health", {{"Origin", "http://evil.example"}})).status, 200);
  // The dashboard's own origin may.
  const std::string own = "http://127.0.0.1:" + std::to_string(s.port());
  EXPECT_EQ(post(s, "/api/v1/renders", kRender, "application/json", {{"Origin", own}}).status, 202);
}

TEST(BrowserPolicy, JsonBodiesMustSayTheyAreJson) {
  const auto& s = test::default_server();
  for (const std::string type : {"text/plain", "application/x-www-form-urlencoded"}) {
    expect_error(post(s, "/api/v1/renders", kRender, type), 415, "unsupported_media_type");
    expect_error(post(s, "/api/v1/envmaps/default/samples", R"({"count":4})", type), 415,
                 "unsupported_media_type");
    expect_error(post(s, "/api/v1/envmaps", R"({"name":"x","path":"forest.exr"})", type), 415,
                 "unsupported_media_type");
  }
  EXPECT_EQ(
      post(s, "/api/v1/envmaps/default/samples", R"({"count":4})", "application/json; charset=utf-8").status,
      200);
  // An image body is an upload whatever it is called; it reaches the decoder.
  expect_error(post(s, "/api/v1/envmaps?name=upload", "PF\n1 1\n-1.0\n", "application/octet-stream"), 422,
               "corrupt");
}

TEST(BrowserPolicy, OnlyThisServersHostNamesAreAnswered) {
  test::ServerProcess s({"--allowed-host", "lightprobe.internal"});
  const auto get_as = [&](const std::string& host) {
    return test::reply(s.client()->Get("/api/v1/health", {{"Host", host}}));
  };
  expect_error(get_as("evil.example"), 403, "host_not_allowed");
  expect_error(get_as("rebind.evil.example:" + std::to_string(s.port())), 403, "host_not_allowed");
  EXPECT_EQ(get_as("localhost:" + std::to_string(s.port())).status, 200);
  EXPECT_EQ(get_as("[::1]:" + std::to_string(s.port())).status, 200);
  EXPECT_EQ(get_as("LightProbe.Internal").status, 200);
  EXPECT_EQ(test::reply(s.client()->Get("/", {{"Host", "evil.example"}})).status, 403);  // static files too
}

TEST(BrowserPolicy, ListedOriginsGetCorsAnswers) {
  test::ServerProcess s({"--cors-origin", "http://app.example:3000"});
  const httplib::Headers preflight = {{"Origin", "http://app.example:3000"},
                                      {"Access-Control-Request-Method", "POST"},
                                      {"Access-Control-Request-Headers", "content-type"}};
  const Reply options = test::reply(s.client()->Options("/api/v1/renders", preflight));
  EXPECT_EQ(options.status, 204) << options.body;
  EXPECT_EQ(options.header("Access-Control-Allow-Origin"), "http://app.example:3000");
  EXPECT_EQ(options.header("Access-Control-Allow-Methods"), "POST, GET");
  EXPECT_NE(options.header("Access-Control-Allow-Headers").find("Content-Type"), std::string::npos);

  const Reply r =
      post(s, "/api/v1/renders", kRender, "application/json", {{"Origin", "http://app.example:3000"}});
  EXPECT_EQ(r.status, 202) << r.body;
  EXPECT_EQ(r.header("Access-Control-Allow-Origin"), "http://app.example:3000");
  expect_error(post(s, "/api/v1/renders", kRender, "application/json", {{"Origin", "http://other.example"}}),
               403, "origin_not_allowed");
}

// A preflight names the headers a page may send (the token, a request id, a revalidation) and how long the
// answer holds; a page may read the ETag and the request id; the answer depends on Origin (Vary).
TEST(BrowserPolicy, PreflightsAndTheHeadersAPageMaySendAndRead) {
  test::ServerProcess s({"--cors-origin", "http://app.example:3000"});
  const Reply options = test::reply(s.client()->Options(
      "/api/v1/envmaps/default", {{"Origin", "http://app.example:3000"},
                                  {"Access-Control-Request-Method", "DELETE"},
                                  {"Access-Control-Request-Headers", "authorization,x-request-id"}}));
  EXPECT_EQ(options.status, 204) << options.body;
  EXPECT_EQ(options.header("Access-Control-Allow-Methods"), "GET, DELETE");
  EXPECT_EQ(options.header("Access-Control-Allow-Headers"),
            "Content-Type, Accept, Authorization, X-Request-Id, If-None-Match");
  EXPECT_EQ(options.header("Access-Control-Max-Age"), "600");
  EXPECT_EQ(options.header("Vary"), "Origin");
  EXPECT_TRUE(options.body.empty());

  const Reply image =
      test::reply(s.client()->Get("/api/v1/envmaps/default/image", {{"Origin", "http://app.example:3000"}}));
  EXPECT_EQ(image.status, 200);
  EXPECT_EQ(image.header("Access-Control-Allow-Origin"), "http://app.example:3000");
  const std::string exposed = image.header("Access-Control-Expose-Headers");
  for (const char* header : {"ETag", "X-Request-Id", "Retry-After", "Location"})
    EXPECT_NE(exposed.find(header), std::string::npos) << header;
  EXPECT_EQ(image.header("Vary"), "Origin");
  // Without an Origin the answer has no CORS headers, but still varies with it.
  const Reply plain = test::reply(s.client()->Get("/api/v1/health"));
  EXPECT_EQ(plain.header("Access-Control-Allow-Origin"), "");
  EXPECT_EQ(plain.header("Vary").find("Origin"), 0u) << plain.header("Vary");
}

TEST(BrowserPolicy, PreflightsFromOtherOriginsAreRefused) {
  for (const auto& args :
       {std::vector<std::string>{}, std::vector<std::string>{"--cors-origin", "http://a.example"}}) {
    test::ServerProcess s(args);
    const Reply r = test::reply(s.client()->Options(
        "/api/v1/renders", {{"Origin", "http://evil.example"}, {"Access-Control-Request-Method", "POST"}}));
    expect_error(r, 403, "origin_not_allowed");
    EXPECT_EQ(r.header("Access-Control-Allow-Origin"), "");
  }
}

TEST(BrowserPolicy, AnyOriginWithAStar) {
  test::ServerProcess s({"--cors-origin", "*"});
  const Reply r = test::reply(s.client()->Get("/api/v1/health", {{"Origin", "http://anywhere.example"}}));
  EXPECT_EQ(r.header("Access-Control-Allow-Origin"), "*");
  EXPECT_EQ(r.header("Vary"), "Accept-Encoding");  // "*" does not depend on the Origin
  const Reply preflight = test::reply(s.client()->Options(
      "/api/v1/renders", {{"Origin", "http://anywhere.example"}, {"Access-Control-Request-Method", "POST"}}));
  EXPECT_EQ(preflight.status, 204);
  EXPECT_EQ(preflight.header("Access-Control-Allow-Origin"), "*");
}

}  // namespace
}  // namespace lp

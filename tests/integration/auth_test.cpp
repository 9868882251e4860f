// --auth-token-file on the real server: every API route but the probes, and /metrics, answer 401 with
// WWW-Authenticate without the token or with another one, and as usual with it; the dashboard's files and
// CORS preflights need none; a file without a usable token stops the start.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;
using test::Reply;

const std::string kToken = "9c2f1e0b7a6d5c4b3a29180706f5e4d3";

std::string token_file(const test::TempDir& dir, const std::string& text) {
  const auto path = dir.path() / "token";
  std::ofstream(path) << text;
  return path.string();
}

Reply get(const test::ServerProcess& s, const std::string& path, const std::string& authorization = "") {
  httplib::Headers headers;
  if (!authorization.empty()) headers.emplace("Authorization", authorization);
  return test::reply(s.client()->Get(path.c_str(), headers));
}

void expect_unauthorized(const Reply& r, const std::string& challenge) {
  EXPECT_EQ(r.status, 401) << r.body;
  EXPECT_EQ(r.header("WWW-Authenticate"), challenge);
  EXPECT_EQ(r.body_json()["error"]["code"], "unauthorized") << r.body;
  EXPECT_EQ(r.body_json()["error"]["request_id"], r.header("X-Request-Id"));
}

const std::string kChallenge = "Bearer realm=\"lightprobe\"";
const std::string kInvalid = "Bearer realm=\"lightprobe\", error=\"invalid_token\"";

TEST(Auth, EveryApiRouteButTheProbesNeedsTheToken) {
  test::TempDir dir;
  test::ServerProcess s({"--auth-token-file", token_file(dir, kToken + "\n")});
  EXPECT_EQ(get(s, "/api/v1/health").status, 200);
  EXPECT_EQ(get(s, "/api/v1/ready").status, 200);
  EXPECT_EQ(get(s, "/").status, 200);  // the dashboard's files

  for (const std::string path : {"/api/v1/envmaps", "/api/v1/envmaps/default/image", "/api/v1/openapi.yaml",
                                 "/api/v1/renders", "/api/v1/no/such/route", "/metrics"}) {
    SCOPED_TRACE(path);
    expect_unauthorized(get(s, path), kChallenge);
    expect_unauthorized(get(s, path, "Basic " + kToken), kChallenge);
    expect_unauthorized(get(s, path, "Bearer " + kToken.substr(1)), kInvalid);
    expect_unauthorized(get(s, path, "Bearer " + kToken + "0"), kInvalid);
    expect_unauthorized(get(s, path, "Bearer " + kToken.substr(0, kToken.size() - 1) + "4"), kInvalid);
    const int status = get(s, path, "Bearer " + kToken).status;
    EXPECT_EQ(status, path == "/api/v1/no/such/route" ? 404 : 200);
    EXPECT_EQ(get(s, path, "bearer  " + kToken).status, status);
  }
  const json render = {
      {"envmap", "default"}, {"scene", {{"preset", "sphere"}}}, {"width", 8}, {"height", 8}, {"spp", 1}};
  auto c = s.client();
  expect_unauthorized(test::reply(c->Post("/api/v1/renders", render.dump(), "application/json")), kChallenge);
  const Reply created = test::reply(
      c->Post("/api/v1/renders", {{"Authorization", "Bearer " + kToken}}, render.dump(), "application/json"));
  EXPECT_EQ(created.status, 202) << created.body;
}

TEST(Auth, PreflightsNeedNoToken) {
  test::TempDir dir;
  test::ServerProcess s(
      {"--auth-token-file", token_file(dir, kToken), "--cors-origin", "http://app.example"});
  const Reply r = test::reply(s.client()->Options(
      "/api/v1/renders", {{"Origin", "http://app.example"},
                          {"Access-Control-Request-Method", "POST"},
                          {"Access-Control-Request-Headers", "authorization, content-type"}}));
  EXPECT_EQ(r.status, 204) << r.body;
  EXPECT_NE(r.header("Access-Control-Allow-Headers").find("Authorization"), std::string::npos);
  // The request itself does, and its 401 can be read by the page.
  const Reply refused = get(s, "/api/v1/envmaps", "");
  EXPECT_EQ(refused.status, 401);
  const Reply cross = test::reply(s.client()->Get("/api/v1/envmaps", {{"Origin", "http://app.example"}}));
  EXPECT_EQ(cross.status, 401);
  EXPECT_EQ(cross.header("Access-Control-Allow-Origin"), "http://app.example");
  EXPECT_NE(cross.header("Access-Control-Expose-Headers").find("WWW-Authenticate"), std::string::npos);
}

TEST(Auth, TheTokenFileFromTheEnvironment) {
  test::TempDir dir;
  test::ServerProcess s({}, {{"LIGHTPROBE_AUTH_TOKEN_FILE", token_file(dir, kToken)}});
  expect_unauthorized(get(s, "/api/v1/envmaps"), kChallenge);
  EXPECT_EQ(get(s, "/api/v1/envmaps", "Bearer " + kToken).status, 200);
}

TEST(Auth, AFileWithoutAUsableTokenStopsTheStart) {
  test::TempDir dir;
  for (const std::string text : {"", "short", "two words here and there", "\"quoted-token-0123456789\""}) {
    const auto run = test::run_until_exit({"--auth-token-file", token_file(dir, text)}, 10s);
    EXPECT_EQ(run.exit_status, 2) << text << ": " << run.output;
    EXPECT_NE(run.output.find("--auth-token-file: "), std::string::npos) << run.output;
  }
  const auto missing = test::run_until_exit({"--auth-token-file", (dir.path() / "absent").string()}, 10s);
  EXPECT_EQ(missing.exit_status, 2);
  EXPECT_NE(missing.output.find("cannot read"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace lp

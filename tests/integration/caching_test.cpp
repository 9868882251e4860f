// Conditional GETs and compression on the real server: images and other pure results carry an ETag of
// their bytes and Cache-Control, If-None-Match is answered with 304; JSON and text of at least
// kGzipMinBytes are gzipped for a client that accepts gzip, smaller bodies and images never are.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "server/http/compression.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

const std::regex kStrongEtag(R"("[0-9a-f]{16}-[0-9a-f]+")");
const std::regex kWeakEtag(R"(W/"[0-9a-f]{16}-[0-9a-f]+")");

// A client that keeps gzipped bodies as they came.
std::unique_ptr<httplib::Client> raw_client(const test::ServerProcess& s) {
  auto c = s.client();
  c->set_decompress(false);
  return c;
}

Reply get(const test::ServerProcess& s, const std::string& path, const httplib::Headers& headers = {}) {
  return test::reply(raw_client(s)->Get(path.c_str(), headers));
}

Reply upload(const test::ServerProcess& s, const std::string& name, const std::vector<uint8_t>& pfm) {
  return test::reply(s.client()->Post(("/api/v1/envmaps?name=" + name).c_str(),
                                      reinterpret_cast<const char*>(pfm.data()), pfm.size(),
                                      "application/octet-stream"));
}

// The answer to a request with If-None-Match: `etag`.
Reply revalidate(const test::ServerProcess& s, const std::string& path, const std::string& etag) {
  return get(s, path, {{"If-None-Match", etag}});
}

TEST(Caching, ImagesHaveAnEtagOfTheirBytesAnd304WhenUnchanged) {
  const auto& s = test::default_server();
  const std::string path = "/api/v1/envmaps/default/image?format=png";
  const Reply first = get(s, path);
  ASSERT_EQ(first.status, 200);
  const std::string etag = first.header("ETag");
  EXPECT_TRUE(std::regex_match(etag, kStrongEtag)) << etag;
  EXPECT_EQ(first.header("Cache-Control"), "no-cache");
  EXPECT_EQ(get(s, path).header("ETag"), etag);
  EXPECT_NE(get(s, path + "&exposure=1").header("ETag"), etag);

  for (const std::string& matching : {etag, "W/" + etag, "\"other\", " + etag, std::string("*")}) {
    const Reply r = revalidate(s, path, matching);
    EXPECT_EQ(r.status, 304) << matching;
    EXPECT_TRUE(r.body.empty());
    EXPECT_EQ(r.header("ETag"), etag);
    EXPECT_EQ(r.header("Cache-Control"), "no-cache");
  }
  const Reply other = revalidate(s, path, "\"0000000000000000-1\"");
  EXPECT_EQ(other.status, 200);
  EXPECT_EQ(other.body, first.body);
  EXPECT_EQ(revalidate(s, path + "&exposure=1", etag).status, 200);
}

TEST(Caching, TheEtagFollowsWhatTheNameHolds) {
  test::ServerProcess s;
  ASSERT_EQ(upload(s, "m", test::grey_map_pfm(8, 4)).status, 201);
  const std::string path = "/api/v1/envmaps/m/image?format=pfm";
  const std::string before = get(s, path).header("ETag");
  EXPECT_EQ(revalidate(s, path, before).status, 304);
  ASSERT_EQ(s.client()->Delete("/api/v1/envmaps/m")->status, 204);
  ASSERT_EQ(upload(s, "m", test::grey_map_pfm(16, 8)).status, 201);
  const Reply after = revalidate(s, path, before);
  EXPECT_EQ(after.status, 200);
  EXPECT_NE(after.header("ETag"), before);
}

TEST(Caching, EveryPureResultRoute) {
  test::ServerProcess s;
  auto c = s.client();
  const json render = {
      {"envmap", "default"}, {"scene", {{"preset", "sphere"}}}, {"width", 8}, {"height", 8}, {"spp", 1}};
  const Reply submitted = test::reply(c->Post("/api/v1/renders", render.dump(), "application/json"));
  ASSERT_EQ(submitted.status, 202);
  const std::string id = submitted.body_json()["id"];
  ASSERT_EQ(test::finished_render(*c, id)["status"], "done");
  const Reply prefilter =
      test::reply(c->Post("/api/v1/envmaps/default/prefilter", R"({"levels":2,"base_size":16,"samples":16})",
                          "application/json"));
  ASSERT_EQ(test::finished_job(*c, prefilter.header("Location"))["status"], "done");
  const std::vector<std::pair<std::string, std::string>> routes = {
      {"/api/v1/envmaps/default/image", "no-cache"},
      {"/api/v1/envmaps/default/distribution", "no-cache"},
      {"/api/v1/envmaps/default/samples.png?count=16", "no-cache"},
      {"/api/v1/envmaps/default/median-cut.png?count=4", "no-cache"},
      {"/api/v1/envmaps/default/sh.png?width=64", "no-cache"},
      {"/api/v1/envmaps/default/image?projection=cube&size=8&format=exr", "no-cache"},
      {"/api/v1/renders/" + id + "/image", "no-cache"},
      {prefilter.header("Location") + "/files/prefiltered.ktx2", "no-cache"},
      {prefilter.header("Location") + "/levels/1.png", "no-cache"},
      {"/api/v1/fresnel?eta_i=1&eta_t=1.5", "max-age=3600"},
      {"/api/v1/brdf-lut?size=8", "max-age=3600"},
      {"/api/v1/fresnel?eta_i=1&eta_t=1.5&format=csv", "max-age=3600"},
      {"/api/v1/openapi.yaml", "max-age=3600"}};
  for (const auto& [path, cache_control] : routes) {
    SCOPED_TRACE(path);
    const Reply r = get(s, path);
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_EQ(r.header("Cache-Control"), cache_control);
    const Reply again = revalidate(s, path, r.header("ETag"));
    EXPECT_EQ(again.status, 304);
    EXPECT_TRUE(again.body.empty());
  }
  // State that changes without its bytes being a result of the request: no ETag.
  for (const std::string& path :
       std::vector<std::string>{"/api/v1/health", "/api/v1/envmaps", "/api/v1/envmaps/default",
                                "/api/v1/renders/" + id, "/metrics"}) {
    const Reply r = get(s, path);
    EXPECT_EQ(r.status, 200) << path;
    EXPECT_EQ(r.header("ETag"), "") << path;
    EXPECT_EQ(r.header("Cache-Control"), "") << path;
  }
}

TEST(Compression, LargeJsonAndTextAreGzippedForClientsThatAcceptIt) {
  const auto& s = test::default_server();
  for (const std::string path :
       {"/api/v1/fresnel?eta_i=1&eta_t=1.5", "/api/v1/fresnel?eta_i=1&eta_t=1.5&format=csv",
        "/api/v1/openapi.yaml", "/metrics"}) {
    SCOPED_TRACE(path);
    const Reply plain = get(s, path, {{"Accept-Encoding", "identity"}});
    ASSERT_EQ(plain.status, 200);
    ASSERT_GE(plain.body.size(), server::kGzipMinBytes);
    EXPECT_EQ(plain.header("Content-Encoding"), "");
    EXPECT_EQ(plain.header("Vary"), "Accept-Encoding");
    const Reply gz = get(s, path, {{"Accept-Encoding", "br;q=1, gzip;q=0.8"}});
    EXPECT_EQ(gz.header("Content-Encoding"), "gzip");
    EXPECT_EQ(gz.header("Vary"), "Accept-Encoding");
    EXPECT_EQ(gz.body.substr(0, 2), "\x1f\x8b");
    EXPECT_LT(gz.body.size(), plain.body.size() / 2);
    // The same bytes once decompressed (by httplib's client).
    const Reply decompressed = test::reply(s.client()->Get(path.c_str(), {{"Accept-Encoding", "gzip"}}));
    if (path != "/metrics") {
      EXPECT_EQ(decompressed.body, plain.body);
    }
    for (const char* refused : {"gzip;q=0", "br", "deflate"})
      EXPECT_EQ(get(s, path, {{"Accept-Encoding", refused}}).header("Content-Encoding"), "") << refused;
  }
}

TEST(Compression, SmallBodiesAndImagesAreNot) {
  const auto& s = test::default_server();
  const Reply health = get(s, "/api/v1/health", {{"Accept-Encoding", "gzip"}});
  ASSERT_LT(health.body.size(), server::kGzipMinBytes);
  EXPECT_EQ(health.header("Content-Encoding"), "");
  EXPECT_EQ(health.header("Vary"), "Accept-Encoding");
  EXPECT_NO_THROW(health.body_json());
  const Reply png = get(s, "/api/v1/envmaps/default/image", {{"Accept-Encoding", "gzip"}});
  ASSERT_GE(png.body.size(), server::kGzipMinBytes);
  EXPECT_EQ(png.header("Content-Encoding"), "");
  EXPECT_EQ(png.header("Vary"), "");
}

TEST(Compression, AGzippedResultHasAWeakEtagAndRevalidates) {
  const auto& s = test::default_server();
  const std::string path = "/api/v1/fresnel?eta_i=1&eta_t=1.33";
  const Reply gz = get(s, path, {{"Accept-Encoding", "gzip"}});
  ASSERT_EQ(gz.header("Content-Encoding"), "gzip");
  const std::string etag = gz.header("ETag");
  EXPECT_TRUE(std::regex_match(etag, kWeakEtag)) << etag;
  const Reply again = get(s, path, {{"Accept-Encoding", "gzip"}, {"If-None-Match", etag}});
  EXPECT_EQ(again.status, 304);
  EXPECT_EQ(again.header("ETag"), etag);
  EXPECT_EQ(again.header("Vary"), "Accept-Encoding");
  // The identity body has the same tag, strong; either form revalidates the other.
  const Reply plain = get(s, path, {{"Accept-Encoding", "identity"}});
  EXPECT_EQ("W/" + plain.header("ETag"), etag);
  EXPECT_EQ(get(s, path, {{"If-None-Match", etag}}).status, 304);
}

}  // namespace
}  // namespace lp

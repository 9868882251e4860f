// The envmap and sampling endpoints over real HTTP against the real server binary.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "support/routes.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::shared_server;

json body_json(const httplib::Result& r) {
  EXPECT_TRUE(r) << "no response";
  return r ? json::parse(r->body, nullptr, false) : json();
}

// Every error is {"error":{"code","message","request_id"}} with the status and the response's X-Request-Id;
// `mention` must appear in the message.
void expect_error(const httplib::Result& r, int status, const std::string& mention = "") {
  ASSERT_TRUE(r) << "no response";
  EXPECT_EQ(r->status, status) << r->body;
  const json j = json::parse(r->body, nullptr, false);
  ASSERT_TRUE(j.contains("error")) << r->body;
  EXPECT_TRUE(j["error"]["code"].is_string());
  EXPECT_EQ(j["error"]["request_id"], r->get_header_value("X-Request-Id")) << r->body;
  EXPECT_NE(j["error"]["message"].get<std::string>().find(mention), std::string::npos) << r->body;
}

httplib::Result upload(httplib::Client& c, const std::string& name, const std::vector<uint8_t>& bytes) {
  return c.Post(("/api/v1/envmaps?name=" + name).c_str(), reinterpret_cast<const char*>(bytes.data()),
                bytes.size(), "application/octet-stream");
}

struct DecodedPng {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

DecodedPng decode_png(const std::string& body) {
  DecodedPng png;
  int n = 0;
  unsigned char* p = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(body.data()),
                                           int(body.size()), &png.width, &png.height, &n, 3);
  if (p) png.rgb.assign(p, p + size_t(png.width) * size_t(png.height) * 3);
  stbi_image_free(p);
  return png;
}

TEST(EnvMapApi, HealthAndListOfPreloadedMaps) {
  auto c = shared_server().client();
  const json health = body_json(c->Get("/api/v1/health"));
  EXPECT_EQ(health["status"], "ok");
  EXPECT_TRUE(health["version"].is_string());
  const json list = body_json(c->Get("/api/v1/envmaps"));
  std::set<std::string> ids;
  for (const auto& m : list["envmaps"]) ids.insert(m["id"]);
  for (const char* id : {"forest_exr", "forest_pfm", "studio_hdr", "city_exr", "sunrise_exr"})
    EXPECT_TRUE(ids.count(id)) << id;
}

TEST(EnvMapApi, UploadsOfEveryFormatGiveTheSameMetadataAsTheEngine) {
  auto c = shared_server().client();
  for (const auto& [file, format] : std::vector<std::pair<std::string, std::string>>{
           {"forest.exr", "exr"}, {"forest.pfm", "pfm"}, {"studio.hdr", "hdr"}}) {
    const std::string name = "up_" + format;
    auto r = upload(*c, name, test::read_bytes(test::envmap_path(file)));
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    EXPECT_EQ(r->get_header_value("Location"), "/api/v1/envmaps/" + name);
    const json m = json::parse(r->body);
    EXPECT_EQ(m["id"], name);
    EXPECT_EQ(m["format"], format);
    EXPECT_EQ(m["width"], test::kRealMapWidth);
    EXPECT_EQ(m["height"], test::kRealMapHeight);
    // power = sum of L * exact pixel solid angle, computed here independently.
    // illuminance = sum over the upper rows of Rec. 709 luminance * the integral of cos theta dOmega
    // over the pixel, (dphi / 2) (cos^2 theta_0 - cos^2 theta_1).
    const Image img = read_image_file(test::envmap_path(file)).image;
    double power_r = 0, illuminance = 0;
    for (int y = 0; y < img.height(); ++y) {
      const double c0 = std::cos(M_PI * y / img.height()), c1 = std::cos(M_PI * (y + 1) / img.height());
      const double omega = (2 * M_PI / img.width()) * (c0 - c1);
      const double projected = 2 * y < img.height() ? (M_PI / img.width()) * (c0 * c0 - c1 * c1) : 0.0;
      for (int x = 0; x < img.width(); ++x) {
        const Rgb v = img.at(x, y);
        power_r += v.x * omega;
        illuminance += (0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z) * projected;
      }
    }
    EXPECT_NEAR(m["power"][0].get<double>(), power_r, 1e-5 * power_r) << file;
    EXPECT_NEAR(m["illuminance"].get<double>(), illuminance, 1e-9 * illuminance) << file;
    EXPECT_NEAR(m["mean_radiance"][0].get<double>(), power_r / (4 * M_PI), 1e-5 * power_r) << file;
    EXPECT_EQ(c->Delete(("/api/v1/envmaps/" + name).c_str())->status, 204);
    EXPECT_EQ(c->Get(("/api/v1/envmaps/" + name).c_str())->status, 404);
  }
}

TEST(EnvMapApi, CurlStyleUploadWithoutContentTypeWorks) {
  auto c = shared_server().client();
  const auto bytes = test::read_bytes(test::envmap_path("forest.pfm"));
  // curl --data-binary sends application/x-www-form-urlencoded unless told otherwise.
  auto r = c->Post("/api/v1/envmaps?name=curl_style", reinterpret_cast<const char*>(bytes.data()),
                   bytes.size(), "application/x-www-form-urlencoded");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 201) << r->body;
  c->Delete("/api/v1/envmaps/curl_style");
}

TEST(EnvMapApi, LoadByPathInsideTheDataDirOnly) {
  auto c = shared_server().client();
  auto r =
      c->Post("/api/v1/envmaps", R"({"name":"by_path","path":"envmaps/sunrise.exr"})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 201) << r->body;
  EXPECT_EQ(json::parse(r->body)["format"], "exr");
  c->Delete("/api/v1/envmaps/by_path");
  expect_error(c->Post("/api/v1/envmaps", R"({"name":"x","path":"../seeds/x.exr"})", "application/json"), 400,
               "path");
  expect_error(c->Post("/api/v1/envmaps", R"({"name":"x","path":"/etc/passwd"})", "application/json"), 400,
               "path");
  expect_error(c->Post("/api/v1/envmaps", R"({"name":"x","path":"envmaps/../../x"})", "application/json"),
               400, "path");
  // A missing file is a bad field of this request (as a missing mesh of a render is), not a missing resource.
  expect_error(c->Post("/api/v1/envmaps", R"({"name":"x","path":"envmaps/none.exr"})", "application/json"),
               400, "field 'path': no file 'envmaps/none.exr'");
  expect_error(c->Post("/api/v1/envmaps", R"({"path":"envmaps/forest.exr"})", "application/json"), 400,
               "name");
  expect_error(
      c->Post("/api/v1/envmaps", R"({"name":"x","path":"envmaps/forest.exr","extra":1})", "application/json"),
      400, "extra");
  expect_error(c->Post("/api/v1/envmaps", R"({"name":"x", "path":)", "application/json"), 400);
  expect_error(
      c->Post("/api/v1/envmaps", R"({"name":"bad/name","path":"envmaps/forest.exr"})", "application/json"),
      400, "name");
}

TEST(EnvMapApi, BadUploadsAreRefusedAndLeaveLoadedMapsAlone) {
  auto c = shared_server().client();
  const json before = body_json(c->Get("/api/v1/envmaps/forest_exr"));
  expect_error(upload(*c, "garbage", {'h', 'e', 'l', 'l', 'o'}), 415);
  auto exr = test::read_bytes(test::envmap_path("forest.exr"));
  exr.resize(exr.size() / 3);
  expect_error(upload(*c, "truncated", exr), 422);
  const std::string nan_pfm =
      std::string("PF\n1 1\n-1.0\n") + std::string("\x00\x00\xc0\x7f\x00\x00\x80\x3f\x00\x00\x80\x3f", 12);
  // One NaN pixel: black under the default policy, which leaves nothing to sample; named under reject.
  expect_error(upload(*c, "nan", std::vector<uint8_t>(nan_pfm.begin(), nan_pfm.end())), 422, "no energy");
  expect_error(upload(*c, "nan&invalid=reject", std::vector<uint8_t>(nan_pfm.begin(), nan_pfm.end())), 422,
               "pixel (0, 0) has a NaN value");
  expect_error(upload(*c, "forest_exr", test::read_bytes(test::envmap_path("studio.hdr"))), 409);
  expect_error(upload(*c, "", test::read_bytes(test::envmap_path("studio.hdr"))), 400, "name");
  expect_error(c->Post("/api/v1/envmaps?name=empty", "", "application/octet-stream"), 400);
  EXPECT_EQ(body_json(c->Get("/api/v1/envmaps/forest_exr")), before);
  for (const char* id : {"garbage", "truncated", "nan", "empty"})
    EXPECT_EQ(c->Get((std::string("/api/v1/envmaps/") + id).c_str())->status, 404);
  EXPECT_TRUE(shared_server().alive());
}

TEST(EnvMapApi, UnknownIdsAre404) {
  auto c = shared_server().client();
  expect_error(c->Get("/api/v1/envmaps/nope"), 404, "nope");
  expect_error(c->Delete("/api/v1/envmaps/nope"), 404);
  expect_error(c->Get("/api/v1/envmaps/nope/image"), 404);
  expect_error(c->Get("/api/v1/envmaps/nope/distribution"), 404);
  expect_error(c->Post("/api/v1/envmaps/nope/samples", R"({"count":1})", "application/json"), 404);
  expect_error(c->Get("/api/v1/envmaps/nope/samples.png"), 404);
  expect_error(c->Get("/api/v1/no/such/endpoint"), 404);
}

TEST(EnvMapApi, ImageInEveryFormat) {
  auto c = shared_server().client();
  // The map as loaded: its few negative values clamped to zero.
  const Image original = EnvMap(read_image_file(test::envmap_path("forest.pfm")).image).image();
  for (const char* format : {"exr", "pfm"}) {
    auto r = c->Get((std::string("/api/v1/envmaps/forest_pfm/image?format=") + format).c_str());
    ASSERT_EQ(r->status, 200);
    const Image back = read_image(std::vector<uint8_t>(r->body.begin(), r->body.end())).image;
    ASSERT_EQ(back.data().size(), original.data().size());
    EXPECT_EQ(std::memcmp(back.data().data(), original.data().data(), original.data().size() * 4), 0)
        << format;
  }
  auto png = c->Get("/api/v1/envmaps/forest_pfm/image?format=png&exposure=1&gamma=2.2");
  ASSERT_EQ(png->status, 200);
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  const DecodedPng d = decode_png(png->body);
  EXPECT_EQ(d.width, test::kRealMapWidth);
  EXPECT_EQ(d.height, test::kRealMapHeight);
  expect_error(c->Get("/api/v1/envmaps/forest_pfm/image?format=gif"), 400, "format");
  expect_error(c->Get("/api/v1/envmaps/forest_pfm/image?exposure=abc"), 400, "exposure");
  expect_error(c->Get("/api/v1/envmaps/forest_pfm/image?gamma=0"), 400, "gamma");
}

TEST(EnvMapApi, DistributionWithAndWithoutSinWeight) {
  auto c = shared_server().client();
  const json w = body_json(c->Get("/api/v1/envmaps/forest_exr/distribution"));
  const json u =
      body_json(c->Get("/api/v1/envmaps/forest_exr/distribution?sin_weight=false&luminance=rec709"));
  for (const json* j : {&w, &u}) {
    EXPECT_EQ((*j)["height"], test::kRealMapHeight);
    ASSERT_EQ((*j)["row_luminance"].size(), size_t(test::kRealMapHeight));
    ASSERT_EQ((*j)["marginal_pdf"].size(), size_t(test::kRealMapHeight));
    ASSERT_EQ((*j)["marginal_cdf"].size(), size_t(test::kRealMapHeight + 1));
    EXPECT_EQ((*j)["marginal_cdf"][0], 0.0);
    EXPECT_DOUBLE_EQ((*j)["marginal_cdf"][size_t(test::kRealMapHeight)].get<double>(), 1.0);
    double sum = 0;
    for (const auto& p : (*j)["marginal_pdf"]) sum += p.get<double>();
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
  // sin weighting scales each row by its solid angle: the pole row against the equator row.
  const size_t equator = test::kRealMapHeight / 2;
  const auto row_weight = [&](size_t y) {
    return w["marginal_pdf"][y].get<double>() / w["row_luminance"][y].get<double>();
  };
  const double expected =
      std::sin(M_PI * 0.5 / test::kRealMapHeight) / std::sin(M_PI * (equator + 0.5) / test::kRealMapHeight);
  EXPECT_NEAR(row_weight(0) / row_weight(equator), expected, 1e-3 * expected);
  expect_error(c->Get("/api/v1/envmaps/forest_exr/distribution?luminance=max"), 400, "luminance");
  expect_error(c->Get("/api/v1/envmaps/forest_exr/distribution?sin_weight=maybe"), 400, "sin_weight");
}

TEST(EnvMapApi, SamplesAsJsonAreReproducibleAndConsistent) {
  auto c = shared_server().client();
  for (const char* strategy : {"independent", "stratified", "sobol"}) {
    const std::string req =
        std::string(R"({"count":1000,"seed":7,"strategy":")") + strategy + R"(","luminance":"rec709"})";
    const json a = body_json(c->Post("/api/v1/envmaps/city_exr/samples", req, "application/json"));
    const json b = body_json(c->Post("/api/v1/envmaps/city_exr/samples", req, "application/json"));
    ASSERT_EQ(a["count"], 1000);
    ASSERT_EQ(a["samples"].size(), 1000u);
    EXPECT_EQ(a, b) << strategy;
    for (const auto& s : a["samples"]) {
      const double theta = s["theta"], phi = s["phi"], u = s["uv"][0], v = s["uv"][1];
      EXPECT_NEAR(theta, v * M_PI, 1e-5);
      EXPECT_NEAR(phi, u * 2 * M_PI, 1e-5);
      EXPECT_NEAR(s["direction"][2].get<double>(), std::cos(theta), 1e-5);
      EXPECT_EQ(s["pixel"][0].get<int>(), int(u * test::kRealMapWidth));
      EXPECT_EQ(s["pixel"][1].get<int>(), int(v * test::kRealMapHeight));
      EXPECT_GT(s["pdf"].get<double>(), 0);
    }
  }
}

TEST(EnvMapApi, BinarySamplesMatchTheJsonOnes) {
  auto c = shared_server().client();
  const std::string req = R"({"count":5000,"seed":3,"strategy":"sobol"})";
  const json j = body_json(c->Post("/api/v1/envmaps/forest_exr/samples", req, "application/json"));
  httplib::Headers accept = {{"Accept", "application/octet-stream"}};
  auto r = c->Post("/api/v1/envmaps/forest_exr/samples", accept, req, "application/json");
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/octet-stream");
  EXPECT_EQ(r->get_header_value("X-Sample-Count"), "5000");
  ASSERT_EQ(r->body.size(), 5000u * 13 * 4);
  std::vector<float> f(5000 * 13);
  std::memcpy(f.data(), r->body.data(), r->body.size());
  for (size_t i = 0; i < 5000; ++i) {
    const json& s = j["samples"][i];
    const float* rec = &f[i * 13];
    ASSERT_EQ(rec[0], s["pixel"][0].get<float>());
    ASSERT_EQ(rec[1], s["pixel"][1].get<float>());
    ASSERT_EQ(rec[2], s["uv"][0].get<float>());
    ASSERT_EQ(rec[9], s["pdf"].get<float>());
    ASSERT_EQ(rec[12], s["radiance"][2].get<float>());
  }
}

TEST(EnvMapApi, LargeBinaryRequestStreams) {
  auto c = shared_server().client();
  httplib::Headers accept = {{"Accept", "application/octet-stream"}};
  auto r = c->Post("/api/v1/envmaps/sunrise_exr/samples", accept, R"({"count":1000000,"seed":1})",
                   "application/json");
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->body.size(), 1000000u * 52);
}

TEST(EnvMapApi, SampleRequestErrorsNameTheField) {
  auto c = shared_server().client();
  const char* url = "/api/v1/envmaps/forest_exr/samples";
  expect_error(c->Post(url, R"({"count":0})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"count":-5})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"count":1.5})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"count":"ten"})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"count":100000000000})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"seed":1})", "application/json"), 400, "count");
  expect_error(c->Post(url, R"({"count":10,"strategy":"halton"})", "application/json"), 400, "strategy");
  expect_error(c->Post(url, R"({"count":10,"luminance":"max"})", "application/json"), 400, "luminance");
  expect_error(c->Post(url, R"({"count":10,"seed":-1})", "application/json"), 400, "seed");
  expect_error(c->Post(url, R"({"count":10,"cout":1})", "application/json"), 400, "cout");
  expect_error(c->Post(url, R"({"count":10)", "application/json"), 400);
  expect_error(c->Post(url, R"([1,2])", "application/json"), 400);
}

TEST(EnvMapApi, SamplePicturesShowWhereSamplesFell) {
  auto c = shared_server().client();
  const json j = body_json(
      c->Post("/api/v1/envmaps/forest_exr/samples", R"({"count":64,"seed":5})", "application/json"));
  auto marks = c->Get("/api/v1/envmaps/forest_exr/samples.png?count=64&seed=5&style=marks");
  ASSERT_EQ(marks->status, 200);
  const DecodedPng m = decode_png(marks->body);
  ASSERT_EQ(m.width, test::kRealMapWidth);
  ASSERT_EQ(m.height, test::kRealMapHeight);
  auto windows = c->Get("/api/v1/envmaps/forest_exr/samples.png?count=64&seed=5&style=windows");
  const DecodedPng w = decode_png(windows->body);
  ASSERT_EQ(w.width, test::kRealMapWidth);
  std::set<std::pair<int, int>> near_sample;
  for (const auto& s : j["samples"]) {
    const int x = s["pixel"][0], y = s["pixel"][1];
    const uint8_t* p = &m.rgb[(size_t(y) * test::kRealMapWidth + x) * 3];
    EXPECT_EQ(p[0], 0);
    EXPECT_EQ(p[1], 0);
    EXPECT_EQ(p[2], 255);
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        near_sample.insert({(x + dx + test::kRealMapWidth) % test::kRealMapWidth, y + dy});
  }
  // Windows: black everywhere except around samples, where the map shows through.
  size_t lit = 0;
  for (int y = 0; y < test::kRealMapHeight; ++y)
    for (int x = 0; x < test::kRealMapWidth; ++x) {
      const uint8_t* p = &w.rgb[(size_t(y) * test::kRealMapWidth + x) * 3];
      const bool black = p[0] == 0 && p[1] == 0 && p[2] == 0;
      if (!near_sample.count({x, y}))
        ASSERT_TRUE(black) << x << "," << y;
      else
        lit += !black;
    }
  EXPECT_GT(lit, 64u);
  expect_error(c->Get("/api/v1/envmaps/forest_exr/samples.png?style=dots"), 400, "style");
  expect_error(c->Get("/api/v1/envmaps/forest_exr/samples.png?count=0"), 400, "count");
}

TEST(EnvMapApi, LimitsFromFlags) {
  test::ServerProcess server({"--max-upload-mb", "1", "--max-pixels", "1000", "--max-samples", "100"});
  auto c = server.client();
  expect_error(upload(*c, "big", test::grey_map_pfm(512, 256)), 413, "max-upload-mb");  // 1.5 MiB body
  expect_error(upload(*c, "many", test::read_bytes(test::envmap_path("forest.exr"))), 413, "pixels");
  expect_error(c->Post("/api/v1/envmaps/default/samples", R"({"count":101})", "application/json"), 400,
               "count");
  EXPECT_EQ(c->Post("/api/v1/envmaps/default/samples", R"({"count":100})", "application/json")->status, 200);
  EXPECT_TRUE(server.alive());
}

TEST(EnvMapApi, DefaultMapWithoutLoadFlags) {
  test::ServerProcess server;
  auto c = server.client();
  const json m = body_json(c->Get("/api/v1/envmaps/default"));
  EXPECT_EQ(m["format"], "procedural");
  EXPECT_GT(m["power"][0].get<double>(), 0);
  EXPECT_EQ(c->Post("/api/v1/envmaps", R"({"name":"x","path":"a.exr"})", "application/json")->status,
            400);  // no --data-dir
}

// Every route the server registers is documented in api/openapi.yaml.
TEST(OpenApi, EveryRegisteredRouteIsDocumented) {
  const std::vector<test::ListedRoute> routes = test::registered_routes();
  ASSERT_GE(routes.size(), 8u);
  std::ifstream in(LIGHTPROBE_OPENAPI);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  for (auto [m, p] : routes) {
    std::transform(m.begin(), m.end(), m.begin(), ::tolower);
    auto it = std::find(lines.begin(), lines.end(), "  " + p + ":");
    ASSERT_NE(it, lines.end()) << p << " is not under paths";
    bool found = false;
    for (++it; it != lines.end() && (it->rfind("    ", 0) == 0 || it->empty()); ++it)
      found |= *it == "    " + m + ":";
    EXPECT_TRUE(found) << m << " " << p << " is not documented";
  }
  // And the document is served.
  auto c = shared_server().client();
  auto r = c->Get("/api/v1/openapi.yaml");
  ASSERT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("openapi: 3.0"), std::string::npos);
}

}  // namespace
}  // namespace lp

// POST /api/v1/envmaps/{id}/median-cut and GET /api/v1/envmaps/{id}/median-cut.png on the real server:
// the lights' shape and totals, caching, the pictures, and every kind of bad input.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

using test::Reply;

Reply post(const test::ServerProcess& s, const std::string& map, const std::string& body) {
  return test::reply(
      s.client()->Post(("/api/v1/envmaps/" + map + "/median-cut").c_str(), body, "application/json"));
}
Reply post(const std::string& map, const std::string& body) {
  return post(test::shared_server(), map, body);
}

Reply get(const test::ServerProcess& s, const std::string& path) {
  return test::reply(s.client()->Get(path.c_str()));
}
Reply get_png(const std::string& map, const std::string& query) {
  return get(test::shared_server(), "/api/v1/envmaps/" + map + "/median-cut.png" + query);
}

struct Png {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  std::array<int, 3> at(int x, int y) const {
    const uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
};

Png decode_png(const std::string& body) {
  Png png;
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(body.data()), int(body.size()),
                                          &png.width, &png.height, &channels, 3);
  if (!pixels) return {};
  png.rgb.assign(pixels, pixels + size_t(png.width) * png.height * 3);
  stbi_image_free(pixels);
  return png;
}

// A 400 naming the field: {"error":{"code":"invalid_field","message":"field 'count': ..."}}.
void expect_field_error(const Reply& r, const std::string& field, const std::string& what) {
  EXPECT_EQ(r.status, 400) << what << ": " << r.body;
  if (r.status != 400) return;
  const json e = r.body_json()["error"];
  EXPECT_EQ(e["code"], "invalid_field") << what << ": " << r.body;
  EXPECT_NE(e["message"].get<std::string>().find("'" + field + "'"), std::string::npos)
      << what << ": " << r.body;
}

TEST(MedianCutApi, LightsOfForestAddUpToTheMapPower) {
  const Reply r =
      post("forest_exr", R"({"count":64,"placement":"centroid","split":"median","luminance":"average"})");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type().rfind("application/json", 0), 0u);
  const json j = r.body_json();
  EXPECT_EQ(j["count"], 64);
  EXPECT_EQ(j["placement"], "centroid");
  EXPECT_EQ(j["split"], "median");
  EXPECT_EQ(j["luminance"], "average");
  EXPECT_GE(j["elapsed_ms"].get<double>(), 0.0);
  ASSERT_EQ(j["lights"].size(), 64u);

  const json meta = get(test::shared_server(), "/api/v1/envmaps/forest_exr").body_json();
  const int w = meta["width"], h = meta["height"];
  std::array<double, 3> sum{};
  double emin = 1e300, emax = 0;
  int64_t pixels = 0;
  for (const json& l : j["lights"]) {
    const double dx = l["direction"][0], dy = l["direction"][1], dz = l["direction"][2];
    EXPECT_NEAR(dx * dx + dy * dy + dz * dz, 1.0, 1e-5);
    const int x0 = l["region"]["x0"], y0 = l["region"]["y0"], x1 = l["region"]["x1"], y1 = l["region"]["y1"];
    EXPECT_TRUE(0 <= x0 && x0 < x1 && x1 <= w && 0 <= y0 && y0 < y1 && y1 <= h) << l.dump();
    pixels += int64_t{x1 - x0} * (y1 - y0);
    const int px = l["pixel"][0], py = l["pixel"][1];
    EXPECT_TRUE(x0 <= px && px < x1 && y0 <= py && py < y1) << l.dump();
    const double u = l["uv"][0], v = l["uv"][1];
    EXPECT_EQ(int(u * w), px);
    EXPECT_EQ(int(v * h), py);
    // The direction is the lat-long direction of uv (z up, theta = v pi, phi = u 2 pi).
    const double theta = v * M_PI, phi = u * 2 * M_PI;
    EXPECT_NEAR(dx, std::sin(theta) * std::cos(phi), 1e-5);
    EXPECT_NEAR(dz, std::cos(theta), 1e-5);
    for (int c = 0; c < 3; ++c) sum[c] += l["power"][c].get<double>();
    const double e = l["energy"];
    EXPECT_NEAR(e,
                (l["power"][0].get<double>() + l["power"][1].get<double>() + l["power"][2].get<double>()) / 3,
                1e-9 * e);
    emin = std::min(emin, e), emax = std::max(emax, e);
  }
  EXPECT_EQ(pixels, int64_t{w} * h);  // the regions tile the map
  for (int c = 0; c < 3; ++c) {
    const double map_power = meta["power"][c];
    EXPECT_NEAR(sum[c], map_power, 1e-5 * map_power);
    EXPECT_NEAR(j["power"][c].get<double>(), map_power, 1e-5 * map_power);
  }
  EXPECT_EQ(j["energy_min"].get<double>(), emin);
  EXPECT_EQ(j["energy_max"].get<double>(), emax);
}

TEST(MedianCutApi, EveryOptionAndAnyCount) {
  for (const char* placement : {"centroid", "centroid_squared", "center"})
    for (const char* split : {"median", "variance"})
      for (const char* luminance : {"average", "rec709"}) {
        const json body = {
            {"count", 100}, {"placement", placement}, {"split", split}, {"luminance", luminance}};
        const Reply r = post("studio_hdr", body.dump());
        ASSERT_EQ(r.status, 200) << body.dump() << ": " << r.body;
        const json j = r.body_json();
        EXPECT_EQ(j["count"], 100);
        EXPECT_EQ(j["lights"].size(), 100u);
        EXPECT_EQ(j["placement"], placement);
        EXPECT_EQ(j["split"], split);
        EXPECT_EQ(j["luminance"], luminance);
      }
  const Reply one = post("city_exr", R"({"count":1})");
  ASSERT_EQ(one.status, 200) << one.body;
  const json region = one.body_json()["lights"][0]["region"];
  EXPECT_EQ(region, (json{{"x0", 0}, {"y0", 0}, {"x1", test::kRealMapWidth}, {"y1", test::kRealMapHeight}}));
}

TEST(MedianCutApi, DefaultsAndRepeatsComeFromTheCache) {
  const Reply first = post("sunrise_exr", "");
  ASSERT_EQ(first.status, 200) << first.body;
  const json a = first.body_json();
  EXPECT_EQ(a["count"], 64);
  EXPECT_EQ(a["placement"], "centroid");
  EXPECT_EQ(a["split"], "median");
  EXPECT_EQ(a["luminance"], "average");
  const Reply again = post("sunrise_exr", R"({"count":64})");
  ASSERT_EQ(again.status, 200);
  const json b = again.body_json();
  EXPECT_TRUE(b["cached"].get<bool>());
  EXPECT_EQ(a["lights"], b["lights"]);
}

TEST(MedianCutApi, PicturesHaveTheMapSize) {
  const Reply regions = get_png("courtyard_exr", "?count=16&style=regions");
  ASSERT_EQ(regions.status, 200) << regions.body;
  EXPECT_EQ(regions.type(), "image/png");
  const Png r = decode_png(regions.body);
  ASSERT_EQ(r.width, test::kRealMapWidth);
  ASSERT_EQ(r.height, test::kRealMapHeight);

  // Every region's top-left cut is green, every light a red dot: check against the JSON.
  const json lights = post("courtyard_exr", R"({"count":16})").body_json()["lights"];
  const std::array<int, 3> green{0, 255, 0}, red{255, 0, 0};
  for (const json& l : lights) {
    const int x0 = l["region"]["x0"], y0 = l["region"]["y0"], x1 = l["region"]["x1"];
    const int px = l["pixel"][0], py = l["pixel"][1];
    EXPECT_EQ(r.at(px, py), red);
    if (x0 > 0 && std::abs(px - x0) > 3) {
      EXPECT_EQ(r.at(x0, py), green) << l.dump();
    }
    if (y0 > 0) {
      EXPECT_EQ(r.at((x0 + x1) / 2, y0), green) << l.dump();
    }
  }

  const Reply dots = get_png("courtyard_exr", "?count=16&style=lights&exposure=2&gamma=2.2");
  ASSERT_EQ(dots.status, 200) << dots.body;
  const Png d = decode_png(dots.body);
  ASSERT_EQ(d.width, test::kRealMapWidth);
  ASSERT_EQ(d.height, test::kRealMapHeight);
  int lit = 0;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) lit += d.at(x, y) != std::array<int, 3>{0, 0, 0};
  EXPECT_GT(lit, 0);
  EXPECT_LE(lit, 16 * 25);  // 16 dots of 5 x 5 at most (dots may overlap)
  for (const json& l : lights) EXPECT_NE(d.at(l["pixel"][0], l["pixel"][1]), (std::array<int, 3>{0, 0, 0}));

  for (const char* query : {"", "?count=256&placement=center&split=variance&luminance=rec709"}) {
    const Reply p = get_png("studio_exr", query);
    ASSERT_EQ(p.status, 200) << query << ": " << p.body;
    const Png img = decode_png(p.body);
    EXPECT_EQ(img.width, test::kRealMapWidth);
    EXPECT_EQ(img.height, test::kRealMapHeight);
  }
}

TEST(MedianCutApi, BadBodiesNameTheField) {
  expect_field_error(post("forest_exr", R"({"count":0})"), "count", "count 0");
  expect_field_error(post("forest_exr", R"({"count":-4})"), "count", "negative count");
  expect_field_error(post("forest_exr", R"({"count":2.5})"), "count", "non-integer count");
  expect_field_error(post("forest_exr", R"({"count":"64"})"), "count", "count as a string");
  expect_field_error(post("forest_exr", R"({"count":65537})"), "count", "count above --max-lights");
  expect_field_error(post("forest_exr", R"({"count":1e12})"), "count", "huge count");
  expect_field_error(post("forest_exr", R"({"placement":"centre"})"), "placement", "unknown placement");
  expect_field_error(post("forest_exr", R"({"split":"mean"})"), "split", "unknown split");
  expect_field_error(post("forest_exr", R"({"luminance":"rec601"})"), "luminance", "unknown luminance");
  expect_field_error(post("forest_exr", R"({"cout":64})"), "cout", "unknown field");
  const Reply bad_json = post("forest_exr", R"({"count":)");
  EXPECT_EQ(bad_json.status, 400);
  EXPECT_EQ(bad_json.body_json()["error"]["code"], "invalid_json");
  const Reply missing = post("no_such_map", R"({"count":4})");
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.body_json()["error"]["code"], "not_found");
}

TEST(MedianCutApi, BadQueriesNameTheField) {
  expect_field_error(get_png("forest_exr", "?count=0"), "count", "count 0");
  expect_field_error(get_png("forest_exr", "?count=-1"), "count", "negative count");
  expect_field_error(get_png("forest_exr", "?count=1.5"), "count", "non-integer count");
  expect_field_error(get_png("forest_exr", "?count=many"), "count", "count not a number");
  expect_field_error(get_png("forest_exr", "?count=65537"), "count", "count above --max-lights");
  expect_field_error(get_png("forest_exr", "?placement=middle"), "placement", "unknown placement");
  expect_field_error(get_png("forest_exr", "?split=half"), "split", "unknown split");
  expect_field_error(get_png("forest_exr", "?style=dots"), "style", "unknown style");
  expect_field_error(get_png("forest_exr", "?exposure=bright"), "exposure", "exposure not a number");
  expect_field_error(get_png("forest_exr", "?gamma=-2"), "gamma", "negative gamma");
  EXPECT_EQ(get_png("no_such_map", "").status, 404);
}

// --max-lights sets the limit; a map smaller than the count asked for is a 400 on `count` too.
TEST(MedianCutApi, LimitsFromTheFlagAndTheMapSize) {
  test::ServerProcess server(
      {"--max-lights", "16", "--load", "forest=" + test::envmap_path("forest.exr").string()});
  expect_field_error(post(server, "forest", R"({"count":17})"), "count", "count above --max-lights 16");
  const Reply ok = post(server, "forest", R"({"count":16})");
  ASSERT_EQ(ok.status, 200) << ok.body;
  EXPECT_EQ(ok.body_json()["lights"].size(), 16u);

  Image tiny(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) tiny.set(x, y, {float(x + 1), float(y + 1), 1.0f});
  const auto pfm = write_pfm(tiny);
  auto up = server.client()->Post("/api/v1/envmaps?name=tiny", std::string(pfm.begin(), pfm.end()),
                                  "application/octet-stream");
  ASSERT_TRUE(up);
  ASSERT_EQ(up->status, 201) << up->body;
  expect_field_error(post(server, "tiny", R"({"count":9})"), "count", "more lights than pixels");
  const Reply each = post(server, "tiny", R"({"count":8})");
  ASSERT_EQ(each.status, 200) << each.body;
  for (const json& l : each.body_json()["lights"]) {
    EXPECT_EQ(l["region"]["x1"].get<int>() - l["region"]["x0"].get<int>(), 1);
    EXPECT_EQ(l["region"]["y1"].get<int>() - l["region"]["y0"].get<int>(), 1);
  }
  EXPECT_TRUE(server.alive());
}

TEST(MedianCutApi, OpenApiDocumentsBothEndpoints) {
  const Reply doc = get(test::shared_server(), "/api/v1/openapi.yaml");
  ASSERT_EQ(doc.status, 200);
  for (const char* path : {"/api/v1/envmaps/{id}/median-cut:", "/api/v1/envmaps/{id}/median-cut.png:",
                           "MedianCutResult:", "MedianCutLight:"})
    EXPECT_NE(doc.body.find(path), std::string::npos) << path;
}

}  // namespace
}  // namespace lp

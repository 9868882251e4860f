// Parsing of median-cut requests and the JSON text of a result.
#include "api/median_cut_request.hpp"

#include <gtest/gtest.h>

#include "api/api_error.hpp"
#include "api/median_cut_schema.hpp"

namespace lp::api {
namespace {

RequestLimits lights(int64_t max) {
  RequestLimits limits;
  limits.max_lights = max;
  return limits;
}

std::string field_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    return e.what();
  }
  return "accepted";
}

TEST(MedianCutRequest, EmptyBodyMeansDefaults) {
  for (const char* body : {"", "  \n", "{}"}) {
    const MedianCutParams p = parse_median_cut_request(body, RequestLimits{});
    EXPECT_EQ(p.count, 64);
    EXPECT_EQ(p.placement, LightPlacement::Centroid);
    EXPECT_EQ(p.split, SplitRule::Median);
    EXPECT_EQ(p.luminance, LuminanceMode::Average);
  }
  const MedianCutParams p = parse_median_cut_request(
      R"({"count":100,"placement":"centroid_squared","split":"variance","luminance":"rec709"})",
      RequestLimits{});
  EXPECT_EQ(p.count, 100);
  EXPECT_EQ(p.placement, LightPlacement::CentroidSquared);
  EXPECT_EQ(p.split, SplitRule::Variance);
  EXPECT_EQ(p.luminance, LuminanceMode::Rec709);
}

TEST(MedianCutRequest, BadFieldsAreNamed) {
  EXPECT_NE(field_of([] { parse_median_cut_request(R"({"count":0})", lights(10)); }).find("'count'"),
            std::string::npos);
  EXPECT_NE(field_of([] { parse_median_cut_request(R"({"count":11})", lights(10)); }).find("'count'"),
            std::string::npos);
  EXPECT_NE(field_of([] { parse_median_cut_request(R"({"count":1.5})", lights(10)); }).find("'count'"),
            std::string::npos);
  EXPECT_NE(
      field_of([] { parse_median_cut_request(R"({"placement":"x"})", lights(10)); }).find("'placement'"),
      std::string::npos);
  EXPECT_NE(field_of([] {
              check_count_fits(parse_median_cut_request(R"({"count":9})", lights(10)), 8);
            }).find("'count'"),
            std::string::npos);
  EXPECT_EQ(field_of([] { check_count_fits(parse_median_cut_request(R"({"count":8})", lights(10)), 8); }),
            "accepted");
}

TEST(MedianCutRequest, ImageQuery) {
  const Query q = {
      {"count", "16"}, {"style", "lights"}, {"split", "variance"}, {"exposure", "-2"}, {"gamma", "2.2"}};
  const MedianCutImageRequest r = parse_median_cut_image_query(q, RequestLimits{});
  EXPECT_EQ(r.params.count, 16);
  EXPECT_EQ(r.params.split, SplitRule::Variance);
  EXPECT_EQ(r.style, MedianCutStyle::Lights);
  EXPECT_EQ(r.tone.exposure, -2.0f);
  EXPECT_EQ(r.tone.gamma, 2.2f);
  EXPECT_EQ(parse_median_cut_image_query({}, RequestLimits{}).style, MedianCutStyle::Regions);
  EXPECT_NE(field_of([] {
              parse_median_cut_image_query({{"style", "dots"}}, lights(10));
            }).find("'style'"),
            std::string::npos);
}

TEST(MedianCutSchema, JsonTextReadsBackExactly) {
  MedianCutResult r;
  r.params.count = 2;
  MedianCutLight a;
  a.direction = {0.6f, 0.8f, 0.0f};
  a.pixel_x = 3, a.pixel_y = 4, a.u = 0.1, a.v = 1.0 / 3.0;
  a.region = {0, 0, 5, 8};
  a.power = {1e-7, 2.5, 1.0 / 7.0};
  a.energy = 0.8809523809523809;
  MedianCutLight b = a;
  b.region = {5, 0, 10, 8};
  r.lights = {a, b};
  r.power = {2e-7, 5.0, 2.0 / 7.0};
  r.energy_min = r.energy_max = a.energy;
  const Json j = Json::parse(median_cut_json(r, 1.25, true));
  EXPECT_EQ(j["count"], 2);
  EXPECT_EQ(j["placement"], "centroid");
  EXPECT_EQ(j["split"], "median");
  EXPECT_EQ(j["luminance"], "average");
  EXPECT_EQ(j["elapsed_ms"].get<double>(), 1.25);
  EXPECT_EQ(j["cached"], true);
  ASSERT_EQ(j["lights"].size(), 2u);
  const Json& l = j["lights"][0];
  EXPECT_EQ(l["direction"][0].get<float>(), 0.6f);
  EXPECT_EQ(l["pixel"], Json::array({3, 4}));
  EXPECT_EQ(l["uv"][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(l["region"], (Json{{"x0", 0}, {"y0", 0}, {"x1", 5}, {"y1", 8}}));
  EXPECT_EQ(l["power"][0].get<double>(), 1e-7);
  EXPECT_EQ(l["power"][2].get<double>(), 1.0 / 7.0);
  EXPECT_EQ(l["energy"].get<double>(), a.energy);
  EXPECT_EQ(j["lights"][1]["region"]["x0"], 5);
  EXPECT_EQ(j["power"][1].get<double>(), 5.0);
}

}  // namespace
}  // namespace lp::api

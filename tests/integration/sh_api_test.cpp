// GET /api/v1/envmaps/{id}/sh and sh.png on the real server: a white map's analytic coefficients, the
// stated conventions, caching, the picture, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/server_process.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

constexpr double kPi = std::numbers::pi;

Reply get(const std::string& path) {
  return test::reply(test::shared_server().client()->Get(path.c_str()));
}

const std::string& white() {
  static const std::string name = test::ensure_white_map(*test::shared_server().client(), "sh_white");
  return name;
}

void expect_rgb(const json& rgb, double value, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c].get<double>(), value, tolerance) << rgb;
}

TEST(ShApi, AWhiteMapIsTwoRootPiOfRadianceAndPiOfIrradiance) {
  const Reply r = get("/api/v1/envmaps/" + white() + "/sh?bands=5");
  ASSERT_EQ(r.status, 200) << r.body;
  const json j = r.body_json();
  EXPECT_EQ(j["bands"], 5);
  EXPECT_EQ(j["coefficient_count"], 25);
  ASSERT_EQ(j["radiance"]["coefficients"].size(), 25u);
  const json l00 = j["radiance"]["coefficients"][0];
  EXPECT_EQ(l00["l"], 0);
  EXPECT_EQ(l00["m"], 0);
  expect_rgb(l00["rgb"], 2 * std::sqrt(kPi), 1e-9);
  for (size_t i = 1; i < 25; ++i) expect_rgb(j["radiance"]["coefficients"][i]["rgb"], 0, 2e-3);
  // E(n) = E00 Y00 = pi for every n; a white Lambertian surface reflects 1.
  const double y00 = 0.5 / std::sqrt(kPi);
  expect_rgb(j["irradiance"]["coefficients"][0]["rgb"], kPi / y00, 1e-9);
  EXPECT_EQ(j["irradiance"]["includes_1_over_pi"], false);
  expect_rgb(j["lambertian"]["coefficients"][0]["rgb"], 1 / y00, 1e-9);
  EXPECT_EQ(j["lambertian"]["includes_1_over_pi"], true);
  EXPECT_NEAR(j["irradiance"]["band_factors"][2].get<double>(), kPi / 4, 1e-12);
  EXPECT_NEAR(j["irradiance"]["band_factors"][4].get<double>(), -kPi / 24, 1e-12);
}

TEST(ShApi, TheAnswerStatesItsConventions) {
  const json j = get("/api/v1/envmaps/forest_exr/sh").body_json();
  EXPECT_EQ(j["bands"], 3);
  EXPECT_EQ(j["radiance"]["coefficients"].size(), 9u);
  EXPECT_EQ(j["convention"]["condon_shortley_phase"], false);
  EXPECT_NE(j["convention"]["basis"].get<std::string>().find("orthonormal"), std::string::npos);
  EXPECT_NE(j["convention"]["frame"].get<std::string>().find("z up"), std::string::npos);
  EXPECT_EQ(j["window"]["name"], "none");
  const json order = j["radiance"]["coefficients"];
  EXPECT_EQ(order[1]["m"], -1);
  EXPECT_EQ(order[3]["m"], 1);
  EXPECT_EQ(order[4]["l"], 2);
  EXPECT_EQ(order[4]["m"], -2);
}

TEST(ShApi, FewerBandsAreThePrefixAndWindowsScaleBands) {
  const json five = get("/api/v1/envmaps/forest_exr/sh?bands=5&irradiance=false").body_json();
  const json two = get("/api/v1/envmaps/forest_exr/sh?bands=2&irradiance=false").body_json();
  EXPECT_FALSE(two.contains("irradiance"));
  for (size_t i = 0; i < 4; ++i)
    EXPECT_EQ(two["radiance"]["coefficients"][i], five["radiance"]["coefficients"][i]);
  EXPECT_TRUE(two["cached"].get<bool>());
  const json hann = get("/api/v1/envmaps/forest_exr/sh?bands=2&window=hann").body_json();
  EXPECT_EQ(hann["window"]["factors"], json::array({1.0, 0.5}));
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(hann["radiance"]["coefficients"][0]["rgb"][c].get<double>(),
                     two["radiance"]["coefficients"][0]["rgb"][c].get<double>());
    EXPECT_NEAR(hann["radiance"]["coefficients"][2]["rgb"][c].get<double>(),
                0.5 * two["radiance"]["coefficients"][2]["rgb"][c].get<double>(), 1e-12);
  }
}

TEST(ShApi, ThePictureOfAWhiteMapIsWhite) {
  const Reply r = get("/api/v1/envmaps/" + white() + "/sh.png?bands=3");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type(), "image/png");
  const auto png = test::decode_png({reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()});
  EXPECT_EQ(png.width, 64);  // as wide as the map
  EXPECT_EQ(png.height, 32);
  for (uint8_t v : png.rgb) EXPECT_GE(v, 254);
  const Reply lambertian =
      get("/api/v1/envmaps/" + white() + "/sh.png?quantity=lambertian&width=40&exposure=-1");
  const auto half =
      test::decode_png({reinterpret_cast<const uint8_t*>(lambertian.body.data()), lambertian.body.size()});
  EXPECT_EQ(half.width, 40);
  EXPECT_EQ(half.height, 20);
  for (uint8_t v : half.rgb) EXPECT_NEAR(v, 188, 1);  // sRGB of 0.5
}

TEST(ShApi, BadQueriesAre400sNamingTheParameter) {
  for (const std::string query :
       {"bands=0", "bands=6", "bands=x", "window=box", "irradiance=maybe", "band=3"}) {
    const Reply r = get("/api/v1/envmaps/forest_exr/sh?" + query);
    EXPECT_EQ(r.status, 400) << query;
    const std::string name = query.substr(0, query.find('='));
    EXPECT_NE(r.body.find("'" + name + "'"), std::string::npos) << query << ": " << r.body;
  }
  for (const std::string query : {"width=1", "width=4097", "quantity=irradiance", "irradiance=true"}) {
    const Reply r = get("/api/v1/envmaps/forest_exr/sh.png?" + query);
    EXPECT_EQ(r.status, 400) << query << ": " << r.body;
  }
  EXPECT_EQ(get("/api/v1/envmaps/no_such_map/sh").status, 404);
  EXPECT_EQ(get("/api/v1/envmaps/no_such_map/sh.png").status, 404);
}

}  // namespace
}  // namespace lp

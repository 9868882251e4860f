// The three target's files: a direction of the world lands where three.js looks for its engine direction
// (u = atan2(e.z, e.x) / 2 pi + 1/2, e = (x, z, -y)), both files carry the same map, no chain is made.
#include <gtest/gtest.h>

#include <cmath>

#include "api/bake/targets.hpp"
#include "api/params.hpp"
#include "api/prefilter_request.hpp"
#include "engine/core/constants.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ultrahdr.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::api {
namespace {

constexpr int kWidth = 64, kHeight = 32;

// One bright texel on the horizon (rows 15 and 16 straddle it) at world azimuth `phi_turns`.
Image spot(double phi_turns) {
  Image img(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) img.set(x, y, {0.01f, 0.01f, 0.01f});
  const int x = int(phi_turns * kWidth);
  img.set(x, kHeight / 2, {4.0f, 2.0f, 1.0f});
  return img;
}

std::vector<BakeFile> bake(const Image& image) {
  const EnvMap map(image);
  const ShCoefficients sh = project_sh(image, 3);
  const PrefilterRequest request;
  return three_target().write(BakeInput{"spot", map, nullptr, sh, request});
}

const BakeFile& file(const std::vector<BakeFile>& files, const std::string& name) {
  for (const BakeFile& f : files)
    if (f.name == name) return f;
  throw std::runtime_error("no " + name);
}

// The column of three.js's map holding the engine direction e (on the horizon, e.y = 0).
int three_column(double ex, double ez) {
  const double u = std::atan2(ez, ex) / (2 * kPi) + 0.5;
  return int(std::floor(u * kWidth));
}

int brightest_column(const Image& img) {
  int best = 0;
  for (int x = 0; x < img.width(); ++x)
    if (img.at(x, kHeight / 2).x > img.at(best, kHeight / 2).x) best = x;
  return best;
}

TEST(BakeThree, WorldDirectionsLandWhereThreeLooks) {
  // Texel centres near world +x, +y, -x, -y: engine (cos phi, 0, -sin phi).
  for (const double turns :
       {0.5 / kWidth, 0.25 + 0.5 / kWidth, 0.5 + 0.5 / kWidth, 0.75 + 0.5 / kWidth, 0.3}) {
    const double phi = 2 * kPi * (std::floor(turns * kWidth) + 0.5) / kWidth;
    const auto files = bake(spot(turns));
    const Image hdr = read_image(file(files, "spot.hdr").bytes).image;
    const Image jpg = decode_ultrahdr(file(files, "spot.jpg").bytes).radiance;
    const int want = three_column(std::cos(phi), -std::sin(phi));
    EXPECT_EQ(brightest_column(hdr), want) << "azimuth " << turns;
    EXPECT_EQ(brightest_column(jpg), want) << "azimuth " << turns;
    EXPECT_NEAR(hdr.at(want, kHeight / 2).x, 4.0f, 0.04f);
    EXPECT_NEAR(jpg.at(want, kHeight / 2).x, 4.0f, 0.3f);
  }
}

TEST(BakeThree, TakesNoChainAndListsItsFiles) {
  EXPECT_FALSE(three_target().chain_params(PrefilterRequest{}).has_value());
  const auto files = bake(spot(0.1));
  ASSERT_EQ(files.size(), 3u);
  const Json manifest = Json::parse(
      std::string(file(files, "manifest.json").bytes.begin(), file(files, "manifest.json").bytes.end()));
  EXPECT_EQ(manifest["target"], "three");
  EXPECT_EQ(manifest["files"][0]["name"], "spot.hdr");
  EXPECT_EQ(manifest["files"][1]["name"], "spot.jpg");
  EXPECT_EQ(manifest["roughness_to_lod"]["prefiltered"], false);
}

}  // namespace
}  // namespace lp::api

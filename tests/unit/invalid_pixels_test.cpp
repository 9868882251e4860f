// The invalid-pixel policy of environment maps: negatives clamped, NaN/Inf/huge pixels black, counted;
// or, under reject, an error naming the first bad pixel. Power and sampling use the sanitised map.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// A night-sky-like map (mean about 0.13) with smooth variation.
Image night_map(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = 0.13f + 0.05f * std::sin(0.3f * float(x)) * std::cos(0.2f * float(y));
      img.set(x, y, {v, 0.9f * v, 1.1f * v});
    }
  return img;
}

// Power computed here from the definition: sum of radiance times the exact solid angle of each pixel
// row, (2 pi / w) (cos theta0 - cos theta1), in double.
Rgb exact_power(const Image& img) {
  double r = 0, g = 0, b = 0;
  const int w = img.width(), h = img.height();
  for (int y = 0; y < h; ++y) {
    const double omega = 2.0 * kPiD / w * (std::cos(kPiD * y / h) - std::cos(kPiD * (y + 1) / h));
    for (int x = 0; x < w; ++x) {
      const Rgb c = img.at(x, y);
      r += omega * c.x, g += omega * c.y, b += omega * c.z;
    }
  }
  return {float(r), float(g), float(b)};
}

void expect_power(const EnvMap& map, const Image& expected_image) {
  const Rgb want = exact_power(expected_image), got = map.power();
  EXPECT_NEAR(got.x, want.x, 1e-5 * want.x);
  EXPECT_NEAR(got.y, want.y, 1e-5 * want.y);
  EXPECT_NEAR(got.z, want.z, 1e-5 * want.z);
}

std::string reject_message(Image img) {
  try {
    EnvMap map(std::move(img), InvalidPixelPolicy::Reject);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::InvalidData);
    return e.what();
  }
  ADD_FAILURE() << "no error under reject";
  return "";
}

TEST(InvalidPixels, SmallNegativesAreClampedCountedAndLeftOutOfThePower) {
  Image noisy = night_map(64, 32);
  // Lossy-codec noise: a few percent of the mean below zero.
  noisy.set(3, 1, {-0.0033f, 0.1f, 0.1f});
  noisy.set(10, 5, {0.1f, -0.002f, -0.001f});
  noisy.set(63, 31, {0.2f, 0.2f, -0.0005f});
  Image clamped = noisy;
  clamped.set(3, 1, {0.0f, 0.1f, 0.1f});
  clamped.set(10, 5, {0.1f, 0.0f, 0.0f});
  clamped.set(63, 31, {0.2f, 0.2f, 0.0f});

  const EnvMap map(noisy);
  EXPECT_EQ(map.invalid_pixels().clamped_negative_values, 4u);
  EXPECT_EQ(map.invalid_pixels().most_negative_value, -0.0033f);
  EXPECT_EQ(map.invalid_pixels().non_finite_pixels, 0u);
  EXPECT_EQ(map.image().at(3, 1), (Rgb{0.0f, 0.1f, 0.1f}));
  expect_power(map, clamped);
  EXPECT_EQ(map.power().x, EnvMap(clamped).power().x);

  EXPECT_NE(reject_message(noisy).find("pixel (3, 1) has a negative value (-0.0033) in channel R"),
            std::string::npos);
}

TEST(InvalidPixels, NonFinitePixelsBecomeBlackAndAreCounted) {
  Image bad = night_map(64, 32);
  bad.set(7, 2, {NAN, 0.1f, 0.1f});
  bad.set(8, 2, {0.1f, INFINITY, 0.1f});
  bad.set(9, 2, {0.1f, 0.1f, -INFINITY});
  bad.set(0, 20, {FLT_MAX, FLT_MAX, FLT_MAX});  // finite, but its luminance and the power would overflow
  Image zeroed = bad;
  for (auto [x, y] : {std::pair{7, 2}, {8, 2}, {9, 2}, {0, 20}}) zeroed.set(x, y, {});

  const EnvMap map(bad);
  EXPECT_EQ(map.invalid_pixels().non_finite_pixels, 4u);
  EXPECT_EQ(map.invalid_pixels().clamped_negative_values, 0u);
  EXPECT_EQ(map.invalid_pixels().most_negative_value, 0.0f);
  expect_power(map, zeroed);
  EXPECT_EQ(map.image().at(0, 20), Rgb{});

  EXPECT_NE(reject_message(bad).find("pixel (7, 2) has a NaN value"), std::string::npos);
}

TEST(InvalidPixels, HugeValuesKeepEveryDerivedQuantityFinite) {
  Image img(16, 8);
  img.set(5, 3, {kMaxRadiance, kMaxRadiance, kMaxRadiance});  // the largest accepted value
  img.set(6, 3, {1e30f, 1.0f, 1.0f});                         // over it: black
  const EnvMap map(std::move(img));
  EXPECT_EQ(map.invalid_pixels().non_finite_pixels, 1u);
  for (float p : {map.power().x, map.power().y, map.power().z}) EXPECT_TRUE(std::isfinite(p) && p > 0);
  EXPECT_TRUE(std::isfinite(map.max_luminance(LuminanceMode::Average)));
  const auto sampler = map.sampler(LuminanceMode::Rec709);
  const EnvSample s = sampler->sample(0.5f, 0.5f);
  EXPECT_EQ(s.pixel_x, 5);
  EXPECT_TRUE(std::isfinite(s.pdf) && s.pdf > 0);
  EXPECT_TRUE(std::isfinite(s.radiance.x / s.pdf));
}

TEST(InvalidPixels, TinyValuesGiveFiniteDensities) {
  Image img(16, 8);
  img.set(2, 4, {1e-44f, 1e-44f, 1e-44f});  // subnormal: the weight total is far below 1 / FLT_MAX
  const EnvMap map(std::move(img));
  const EnvSample s = map.sampler(LuminanceMode::Average)->sample(0.3f, 0.7f);
  EXPECT_EQ(s.pixel_x, 2);
  EXPECT_EQ(s.pixel_y, 4);
  EXPECT_TRUE(std::isfinite(s.pdf) && s.pdf > 0) << s.pdf;
}

TEST(InvalidPixels, PolicyNamesRoundTrip) {
  for (const std::string& name : enum_names<InvalidPixelPolicy>())
    EXPECT_EQ(enum_name(*parse_enum<InvalidPixelPolicy>(name)), name);
  EXPECT_FALSE(parse_enum<InvalidPixelPolicy>("zero"));
  EXPECT_EQ(enum_name(kDefaultInvalidPixelPolicy), std::string("clamp"));
}

}  // namespace
}  // namespace lp

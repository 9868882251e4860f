// The environment-map importance sampler against analytic answers and its own pdf.
#include "engine/envmap/envmap_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/envmap/sample_set.hpp"
#include "support/chi_square.hpp"
#include "support/constant_map.hpp"
#include "support/real_maps.hpp"

namespace lp {
namespace {

using test::constant_map;

EnvMap one_bright_pixel(int w, int h, int px, int py, Rgb value) {
  Image img(w, h);
  img.set(px, py, value);
  return EnvMap(std::move(img));
}

TEST(LatLong, DirectionAndUvRoundTrip) {
  Rng rng(7, 0);
  for (int i = 0; i < 10000; ++i) {
    const latlong::Uv uv{rng.uniform_float(), rng.uniform_float()};
    const latlong::Uv back = latlong::uv(latlong::direction(uv));
    EXPECT_NEAR(back.v, uv.v, 2e-6f);
    if (uv.v > 1e-3f && uv.v < 1 - 1e-3f) {  // phi is undefined at the poles
      const float du = std::abs(back.u - uv.u);
      EXPECT_LT(std::min(du, 1 - du), 2e-5f) << uv.u << " " << uv.v;
    }
  }
}

TEST(LatLong, ConventionsMatchTheGuide) {
  // u = 0.25, v = 0.5: theta = pi/2, phi = pi/2 -> +y on the equator. v = 0 is +z.
  const Vec3 d = latlong::direction({0.25f, 0.5f});
  EXPECT_NEAR(d.x, 0, 1e-6);
  EXPECT_NEAR(d.y, 1, 1e-6);
  EXPECT_NEAR(d.z, 0, 1e-6);
  EXPECT_NEAR(latlong::direction({0.0f, 0.0f}).z, 1, 1e-6);
  // Pixel solid angles add up to 4 pi.
  double total = 0;
  for (int y = 0; y < 512; ++y) total += 1024 * latlong::pixel_solid_angle(y, 1024, 512);
  EXPECT_NEAR(total, 4 * kPi, 1e-9);
}

TEST(EnvMapSampler, PowerOfAConstantMapIsFourPiTimesRadiance) {
  const EnvMap map = constant_map(64, 32, {1, 2, 3});
  EXPECT_NEAR(map.power().x, 4 * kPi, 1e-5);
  EXPECT_NEAR(map.power().z, 12 * kPi, 1e-4);
  EXPECT_NEAR(map.mean_radiance().y, 2, 1e-6);
}

// Integrates the solid-angle pdf over the sphere on a grid 4x finer than the pixels (exact for a
// piecewise-constant density up to the midpoint rule in theta).
TEST(EnvMapSampler, PdfIntegratesToOneOverTheSphere) {
  const auto map = test::real_map("forest.exr");
  const auto sampler = map->sampler(LuminanceMode::Average);
  const int nu = 4 * map->width(), nv = 4 * map->height();
  double integral = 0;
  for (int j = 0; j < nv; ++j) {
    const double theta = kPi * (j + 0.5) / nv;
    const double d_omega = (2 * kPi / nu) * (kPi / nv) * std::sin(theta);
    for (int i = 0; i < nu; ++i) {
      const latlong::Uv uv{float((i + 0.5) / nu), float((j + 0.5) / nv)};
      integral += sampler->pdf(latlong::direction(uv)) * d_omega;
    }
  }
  EXPECT_NEAR(integral, 1.0, 1e-3);
}

TEST(EnvMapSampler, PdfOfTheSampledDirectionEqualsTheReturnedPdf) {
  const auto map = test::real_map("city.exr");
  for (auto mode : {LuminanceMode::Average, LuminanceMode::Rec709}) {
    const auto sampler = map->sampler(mode);
    Rng rng(3, 0);
    for (int i = 0; i < 100000; ++i) {
      const EnvSample s = sampler->sample(rng.uniform_float(), rng.uniform_float());
      ASSERT_GT(s.pdf, 0);
      // Through acos/atan2 and back, a direction can land one pixel over at a pixel edge.
      const int px = latlong::pixel_x(latlong::uv(s.direction).u, map->width());
      const int py = latlong::pixel_y(latlong::uv(s.direction).v, map->height());
      if (px != s.pixel_x || py != s.pixel_y) continue;
      ASSERT_NEAR(sampler->pdf(s.direction), s.pdf, 1e-4f * s.pdf) << "sample " << i;
      ASSERT_EQ(s.radiance, map->radiance(s.direction));  // the same grid as the pdf
    }
  }
}

TEST(EnvMapSampler, OneBrightPixelGivesTheMapPowerForEverySample) {
  for (int py : {3, 16, 28}) {
    const EnvMap map = one_bright_pixel(64, 32, 40, py, {5, 10, 20});
    const auto sampler = map.sampler(LuminanceMode::Average);
    // radiance / pdf = L 2 pi^2 sin(theta) / (W H) varies with theta inside the pixel; the map's
    // power uses the pixel's exact solid angle. Both lie within the pixel's range of sin(theta).
    const double s0 = std::sin(kPi * py / 32), s1 = std::sin(kPi * (py + 1) / 32);
    const double tolerance = (std::max(s0, s1) - std::min(s0, s1)) / std::min(s0, s1);
    Rng rng(11, 0);
    for (int i = 0; i < 2000; ++i) {
      const EnvSample s = sampler->sample(rng.uniform_float(), rng.uniform_float());
      ASSERT_EQ(s.pixel_x, 40);
      ASSERT_EQ(s.pixel_y, py);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(s.radiance[c] / s.pdf / map.power()[c], 1.0, tolerance) << "row " << py;
    }
  }
}

TEST(EnvMapSampler, ConstantMapGivesTheUniformSpherePdf) {
  const EnvMap map = constant_map(256, 128, {1, 1, 1});
  const auto sampler = map.sampler(LuminanceMode::Average);
  const double uniform = 1.0 / (4 * kPi);
  // At pixel centres the pdf is uniform up to the grid's sum of sin(theta) against its integral.
  for (int y = 0; y < 128; ++y) {
    const latlong::Uv uv{0.3f, float((y + 0.5) / 128)};
    EXPECT_NEAR(sampler->pdf(latlong::direction(uv)), uniform, 2e-4 * uniform) << "row " << y;
  }
}

TEST(EnvMapSampler, PolesNeverGiveNanOrInf) {
  const auto map = test::real_map("sunrise.exr");
  const auto sampler = map->sampler(LuminanceMode::Average);
  for (float u2 : {0.0f, 1e-9f, 1e-7f, 0.5f, 1.0f - 1e-7f, kOneMinusEpsilon}) {
    for (float u1 : {0.0f, 0.5f, kOneMinusEpsilon}) {
      const EnvSample s = sampler->sample(u1, u2);
      ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf > 0) << u1 << " " << u2;
      ASSERT_TRUE(std::isfinite(s.direction.x) && std::isfinite(s.direction.z));
    }
  }
  for (Vec3 pole : {Vec3{0, 0, 1}, Vec3{0, 0, -1}}) EXPECT_TRUE(std::isfinite(sampler->pdf(pole)));
}

TEST(EnvMapSampler, AllZeroMapIsAnError) {
  const EnvMap map = constant_map(8, 4, {0, 0, 0});
  EXPECT_THROW(map.sampler(LuminanceMode::Average), Error);
}

// Expected counts per (phi, cos theta) bin: N times the integral of the pdf over the bin, which is
// the integral of the unit-square density over the bin's (u, v) rectangle (d omega = 2 pi^2 sin
// theta du dv cancels the 1 / (2 pi^2 sin theta)), computed exactly per overlapped pixel.
std::vector<double> expected_counts(const EnvMapSampler& s, int phi_bins, int cos_bins, double n) {
  const auto& dist = s.distribution();
  const int w = dist.width(), h = dist.height();
  std::vector<double> expected(size_t(phi_bins) * cos_bins, 0.0);
  for (int b = 0; b < cos_bins; ++b) {
    // cos theta from 1 (top) down to -1: bin b spans cos in [1 - 2(b+1)/n, 1 - 2b/n].
    const double v0 = std::acos(1.0 - 2.0 * b / cos_bins) / kPi,
                 v1 = std::acos(1.0 - 2.0 * (b + 1) / cos_bins) / kPi;
    for (int y = int(v0 * h); y < std::min(h, int(std::ceil(v1 * h))); ++y) {
      const double ov = std::min(v1, double(y + 1) / h) - std::max(v0, double(y) / h);
      if (ov <= 0) continue;
      for (int x = 0; x < w; ++x) {
        const int a = x * phi_bins / w;  // pixel columns nest inside phi bins (w is a multiple)
        expected[size_t(b) * phi_bins + a] += dist.density(x, y) * ov * (1.0 / w);
      }
    }
  }
  for (double& e : expected) e *= n;
  return expected;
}

template <class Draw>
test::ChiSquareResult chi_square_of(const EnvMapSampler& s, int n, Draw draw) {
  const int phi_bins = 128, cos_bins = 64;
  std::vector<double> observed(size_t(phi_bins) * cos_bins, 0.0);
  for (int i = 0; i < n; ++i) {
    const EnvSample smp = draw(i);
    const int a = std::min(phi_bins - 1, int(smp.phi / (2 * kPi) * phi_bins));
    const int b = std::min(cos_bins - 1, int((1.0 - std::cos(double(smp.theta))) / 2.0 * cos_bins));
    observed[size_t(b) * phi_bins + a] += 1;
  }
  return test::chi_square_test(observed, expected_counts(s, phi_bins, cos_bins, n));
}

// The ways a sample set reaches the sampler: independent uniforms, stratified and sobol points
// through the inverse CDF (its guide tables), and independent sets through the alias table.
enum class Draw { IndependentInverseCdf, Stratified, Sobol, IndependentAlias };
const char* draw_name(Draw d) {
  constexpr const char* kNames[] = {"independent_inverse_cdf", "stratified", "sobol", "independent_alias"};
  return kNames[int(d)];
}

std::vector<EnvSample> draw_samples(const EnvMapSampler& sampler, Draw draw, size_t n, uint64_t seed) {
  std::vector<EnvSample> out(n);
  if (draw == Draw::IndependentInverseCdf) {
    for (size_t i = 0; i < n; ++i) {
      Rng rng(seed, i);
      out[i] = sampler.sample(rng.uniform_float(), rng.uniform_float());
    }
    return out;
  }
  const SampleStrategy strategy = draw == Draw::Stratified ? SampleStrategy::Stratified
                                  : draw == Draw::Sobol    ? SampleStrategy::Sobol
                                                           : SampleStrategy::Independent;
  generate_samples(sampler, {strategy, n, seed}, 0, out);
  return out;
}

constexpr Draw kDraws[] = {Draw::IndependentInverseCdf, Draw::Stratified, Draw::Sobol,
                           Draw::IndependentAlias};
constexpr LuminanceMode kModes[] = {LuminanceMode::Average, LuminanceMode::Rec709};

using RealMapCase = std::tuple<std::string, LuminanceMode, Draw>;
class ChiSquareOnRealMaps : public ::testing::TestWithParam<RealMapCase> {};

TEST_P(ChiSquareOnRealMaps, SamplesMatchTheSamplersPdf) {
  const auto& [name, mode, draw] = GetParam();
  const auto sampler = test::real_map(name)->sampler(mode);
  const auto samples = draw_samples(*sampler, draw, 1'000'000, 12345);
  const auto r = chi_square_of(*sampler, int(samples.size()), [&](int i) { return samples[size_t(i)]; });
  EXPECT_GT(r.p_value, 0.01) << r.summary();
  RecordProperty("chi_square", r.summary());
}

std::string real_map_case_name(const ::testing::TestParamInfo<RealMapCase>& info) {
  const std::string& name = std::get<0>(info.param);
  return name.substr(0, name.find('.')) + "_" + enum_name(std::get<1>(info.param)) + "_" +
         draw_name(std::get<2>(info.param));
}

INSTANTIATE_TEST_SUITE_P(RealMaps, ChiSquareOnRealMaps,
                         ::testing::Combine(::testing::Values("forest.exr", "city.exr", "studio.hdr"),
                                            ::testing::ValuesIn(kModes), ::testing::ValuesIn(kDraws)),
                         real_map_case_name);

// Per pixel, on a small map with a bright spot, black rows and a gradient: the guide tables meet
// cells of zero width and CDF steps of every size.
using PerPixelCase = std::tuple<LuminanceMode, Draw>;
class ChiSquarePerPixel : public ::testing::TestWithParam<PerPixelCase> {};

TEST_P(ChiSquarePerPixel, CountsMatchDensityTimesArea) {
  const auto& [mode, draw] = GetParam();
  Image image(64, 32);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Vec3 d = latlong::direction({(float(x) + 0.5f) / 64.0f, (float(y) + 0.5f) / 32.0f});
      if (d.z < -0.8f) continue;
      const float spot = dot(d, normalize(Vec3{1, 1, 0.5f})) > 0.95f ? 40.0f : 0.0f;
      image.set(x, y, {1.2f + spot + d.z, 0.5f + 0.3f * d.x, 0.1f});
    }
  const EnvMap map(std::move(image));
  const auto sampler = map.sampler(mode);
  const auto& dist = sampler->distribution();
  const int w = map.width(), h = map.height();
  constexpr size_t kN = 200000;
  std::vector<double> observed(size_t(w * h), 0.0), expected(size_t(w * h), 0.0);
  for (const EnvSample& s : draw_samples(*sampler, draw, kN, 6)) {
    const latlong::Uv uv = latlong::uv(s.direction);
    observed[size_t(latlong::pixel_y(uv.v, h) * w + latlong::pixel_x(uv.u, w))] += 1;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) expected[size_t(y * w + x)] = kN * double(dist.density(x, y)) / (w * h);
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, 0.01) << r.summary();
}

std::string per_pixel_case_name(const ::testing::TestParamInfo<PerPixelCase>& info) {
  return std::string(enum_name(std::get<0>(info.param))) + "_" + draw_name(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Draws, ChiSquarePerPixel,
                         ::testing::Combine(::testing::ValuesIn(kModes), ::testing::ValuesIn(kDraws)),
                         per_pixel_case_name);

// MIS compensation: pixels weigh their luminance above the map's solid-angle mean, times sin(theta).
TEST(CompensatedSampler, WeighsOnlyTheLuminanceAboveTheMapsMean) {
  const EnvMap map = [] {
    Image image(16, 8);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x) image.set(x, y, Rgb{float(x % 5), float(y), 0.5f} * 0.7f);
    return EnvMap(std::move(image));
  }();
  const auto sampler = map.sampler(LuminanceMode::Average, SamplerWeights::MisCompensated);
  const float mean = luminance(map.mean_radiance(), LuminanceMode::Average);
  EXPECT_FLOAT_EQ(sampler->luminance_offset(), mean);
  std::vector<double> weights;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      weights.push_back(
          std::max(0.0, double(luminance(map.image().at(x, y), LuminanceMode::Average)) - mean) *
          std::sin(latlong::row_centre_theta(y, 8)));
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  int zero = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      const double expected = weights[size_t(y * 16 + x)] * 16 * 8 / total;  // density: mean 1 per pixel
      EXPECT_NEAR(sampler->distribution().density(x, y), expected, 1e-5 * (1 + expected)) << x << ", " << y;
      zero += expected == 0;
    }
  EXPECT_GT(zero, 16);  // the darker pixels are left to BSDF samples
}

TEST(CompensatedSampler, AUniformMapKeepsThePlainWeights) {
  const EnvMap map = constant_map(64, 32, {2, 2, 2});
  const auto plain = map.sampler(LuminanceMode::Average);
  const auto compensated = map.sampler(LuminanceMode::Average, SamplerWeights::MisCompensated);
  EXPECT_EQ(compensated->luminance_offset(), 0.0f);
  for (int y = 0; y < map.height(); y += 7)
    for (int x = 0; x < map.width(); x += 5)
      EXPECT_EQ(compensated->distribution().density(x, y), plain->distribution().density(x, y));
}

class ChiSquareCompensated : public ::testing::TestWithParam<std::tuple<std::string, Draw>> {};

TEST_P(ChiSquareCompensated, SamplesMatchTheSamplersPdf) {
  const auto& [name, draw] = GetParam();
  const auto sampler = test::real_map(name)->sampler(LuminanceMode::Average, SamplerWeights::MisCompensated);
  ASSERT_GT(sampler->luminance_offset(), 0.0f);
  const auto samples = draw_samples(*sampler, draw, 1'000'000, 777);
  const auto r = chi_square_of(*sampler, int(samples.size()), [&](int i) { return samples[size_t(i)]; });
  EXPECT_GT(r.p_value, 0.01) << r.summary();
}

std::string compensated_case_name(const ::testing::TestParamInfo<std::tuple<std::string, Draw>>& info) {
  const std::string& name = std::get<0>(info.param);
  return name.substr(0, name.find('.')) + "_" + draw_name(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(RealMaps, ChiSquareCompensated,
                         ::testing::Combine(::testing::Values("forest.exr", "city.exr", "studio.hdr"),
                                            ::testing::Values(Draw::Sobol, Draw::IndependentAlias)),
                         compensated_case_name);

// A biased sampler must fail the same test, or the test proves nothing.
TEST(ChiSquare, DetectsASamplerThatIgnoresSinTheta) {
  const auto map = test::real_map("forest.exr");
  const auto sampler = map->sampler(LuminanceMode::Average);
  const auto r = chi_square_of(*sampler, 1'000'000, [&](int i) {
    Rng rng(5, uint64_t(i));
    EnvSample s = sampler->sample(rng.uniform_float(), rng.uniform_float());
    // Move the sample in theta as if rows were not sin-weighted: v -> v^1.1.
    s.theta = float(kPi * std::pow(s.theta / kPi, 1.1));
    return s;
  });
  EXPECT_LT(r.p_value, 1e-6) << r.summary();
}

}  // namespace
}  // namespace lp

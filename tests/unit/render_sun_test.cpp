// Renders with the map's sun taken out as a cone light (lighting.sun = extract): the cone is sampled
// uniformly with the pdf it states, the lighting is the map's (the same mean image as without the sun,
// within noise), and a map without a sun renders exactly as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/render/sun_light.hpp"
#include "engine/sun/sun_extraction.hpp"
#include "render_test_helpers.hpp"
#include "support/chi_square.hpp"
#include "support/sunny_map.hpp"

namespace lp::render {
namespace {

// A 256 x 128 smooth sky with a sun of radius `radius_deg` carrying about 70% of the map's power.
std::shared_ptr<const EnvMap> sunny_map(double radius_deg = 2) {
  Image image = lp::test::latlong_image(256, lp::test::smooth_sky);
  lp::test::add_sun(image, 50, 230, radius_deg,
                    Rgb{1.0f, 0.9f, 0.75f} * float(9000 / (radius_deg * radius_deg)));
  return std::make_shared<const EnvMap>(std::move(image));
}

Lighting envmap_lighting(SunMode sun) {
  Lighting l = test::lighting(LightingMode::EnvMap);
  l.sun = sun;
  return l;
}

TEST(RenderSun, TheConeIsSampledUniformlyWithItsPdf) {
  const auto map = sunny_map(4);
  const SunExtraction e = extract_sun(*map, SunParams{});
  ASSERT_TRUE(e.sun) << e.reason;
  Lighting l = envmap_lighting(SunMode::Extract);
  l.rotation_deg = 30;
  l.intensity = 2;
  const EnvLight env(e.residual, l);
  const SunLight sun(*e.sun, env, *e.residual);
  const double omega = cone_solid_angle(e.sun->angular_radius);
  EXPECT_NEAR(sun.pdf() * omega, 1.0, 1e-6);
  EXPECT_NEAR(sun.radiance().x * omega, 2 * e.sun->power[0], 1e-5 * e.sun->power[0]);

  // Cells of equal solid angle: 1 - cos theta in 8 equal steps of 1 - cos r, phi in 16.
  const Vec3 axis = normalize(env.to_world(e.sun->direction));
  const Frame frame = Frame::from_normal(axis);
  constexpr int kT = 8, kPhi = 16, kN = 200000;
  std::vector<double> observed(kT * kPhi, 0.0), expected(kT * kPhi, double(kN) / (kT * kPhi));
  const double one_minus_cos = 1 - std::cos(e.sun->angular_radius);
  Rng rng(5, 6);
  for (int i = 0; i < kN; ++i) {
    const LightSample s = sun.sample({rng.uniform_float(), rng.uniform_float()});
    ASSERT_TRUE(sun.contains(s.direction));
    ASSERT_EQ(s.pdf, sun.pdf());
    const Vec3 local = frame.to_local(s.direction);
    const Vec3 chord = s.direction - axis;
    const double t = 0.5 * double(dot(chord, chord)) / one_minus_cos;
    double phi = std::atan2(double(local.y), double(local.x));
    if (phi < 0) phi += 2 * kPi;
    const int ti = std::min(kT - 1, int(t * kT)), pi = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
    observed[size_t(ti * kPhi + pi)] += 1;
  }
  const auto chi = lp::test::chi_square_test(observed, expected);
  EXPECT_GT(chi.p_value, 1e-3) << chi.summary();
  // Just outside the cone: not the sun.
  const Vec3 outside = normalize(axis + frame.s * float(1.05 * std::tan(e.sun->angular_radius)));
  EXPECT_FALSE(sun.contains(outside));
  EXPECT_TRUE(sun.contains(normalize(axis + frame.s * float(0.95 * std::tan(e.sun->angular_radius)))));
}

TEST(RenderSun, LightSamplesGoToTheSunWhereItLightsTheSurface) {
  const auto map = sunny_map(4);
  const SunExtraction e = extract_sun(*map, SunParams{});
  ASSERT_TRUE(e.sun) << e.reason;
  Lighting l = envmap_lighting(SunMode::Extract);
  l.rotation_deg = 30;
  const EnvLight env(e.residual, l);
  const SunLight sun(*e.sun, env, *e.residual);
  const Vec3 axis = normalize(env.to_world(e.sun->direction));
  EXPECT_GT(sun.selection(axis), 0.5f);          // the sun holds most of the map's power
  EXPECT_FLOAT_EQ(sun.selection(-axis), 0.05f);  // the least: facing away, the sun gives nothing
  const Vec3 side = Frame::from_normal(axis).s;
  EXPECT_LT(sun.selection(side), sun.selection(axis));
}

double image_mean(const Image& image) {
  double sum = 0;
  for (float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

TEST(RenderSun, TheLightingIsTheMapsWithOrWithoutTheSun) {
  // The diffuse sphere: over four seeds the two modes' means differ by at most 2e-4. The materials
  // preset's caustics (the sun through the glass sphere and off the mirror) are noisy: at 1024 spp the
  // means of four seeds spread by 0.8% in either mode and average the same (1.0967).
  const auto map = sunny_map();
  struct Case {
    const char* preset;
    float rotation_deg;  // turns the sun to another side of the sphere
    int spp;
    double tolerance;  // relative, on the image's mean
  };
  for (const Case& c :
       {Case{"sphere", 0, 256, 2e-3}, Case{"sphere", 100, 256, 2e-3}, Case{"materials", 0, 1024, 0.02}}) {
    const SceneDesc scene = *scene_preset(c.preset);
    Lighting none = envmap_lighting(SunMode::None), extract = envmap_lighting(SunMode::Extract);
    none.rotation_deg = extract.rotation_deg = c.rotation_deg;
    const double a = image_mean(test::render(scene, none, test::settings(32), map, c.spp));
    const double b = image_mean(test::render(scene, extract, test::settings(32), map, c.spp));
    std::printf("%s, rotated %g degrees, %d spp: mean %.5f without the sun, %.5f with it (%+.4f)\n", c.preset,
                double(c.rotation_deg), c.spp, a, b, b / a - 1);
    EXPECT_NEAR(b / a, 1.0, c.tolerance) << c.preset << " " << c.rotation_deg;
  }
}

TEST(RenderSun, AMapWithoutASunRendersAsBeforeAndTheFurnaceStaysExact) {
  const SceneDesc scene = *scene_preset("furnace");
  const auto white = test::constant_map(1.0f);
  const Image none = test::render(scene, envmap_lighting(SunMode::None), test::settings(32), white, 64);
  const Image extract = test::render(scene, envmap_lighting(SunMode::Extract), test::settings(32), white, 64);
  ASSERT_EQ(none.data().size(), extract.data().size());
  for (size_t i = 0; i < none.data().size(); ++i) ASSERT_EQ(none.data()[i], extract.data()[i]) << i;
  EXPECT_NEAR(test::sphere_mean(extract), 0.5, 2e-3);
}

TEST(RenderSun, ExtractNeedsTheEnvmapMode) {
  Lighting l = test::lighting(LightingMode::Uniform);
  l.sun = SunMode::Extract;
  try {
    l.validate("lighting");
    FAIL() << "accepted sun extract with mode uniform";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "lighting.sun");
  }
}

}  // namespace
}  // namespace lp::render

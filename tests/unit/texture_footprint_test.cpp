// Texture lookups over a ray cone's footprint: the ellipse a cone draws on a surface seen at an angle
// (its axes' ratio 1 / cos), its principal axes in texture coordinates, and the anisotropic filter
// over it (one trilinear lookup when round, probes along the major axis at the minor axis' level
// otherwise, the elongation bounded, the texture transform applied to the axes).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/model_shading.hpp"
#include "engine/texture/texture.hpp"
#include "model_test_scenes.hpp"

namespace lp::render {
namespace {

constexpr float kDeg = kPiF / 180;

TEST(TextureFootprint, PrincipalAxesOfConjugateDiameters) {
  // [[1, 1], [0, 1]] has singular values phi and 1 / phi; the major axis is the eigenvector of
  // [[2, 1], [1, 1]] for phi^2, (phi, 1) normalised.
  const float phi = 0.5f * (1 + std::sqrt(5.0f));
  const FootprintAxes skew = principal_axes({{1, 0}, {1, 1}});
  EXPECT_NEAR(skew.major_width, phi, 1e-6f);
  EXPECT_NEAR(skew.minor_width, 1 / phi, 1e-6f);
  const float n = std::hypot(phi, 1.0f);
  EXPECT_NEAR(std::abs(skew.major.x), phi / n, 1e-6f);
  EXPECT_NEAR(std::abs(skew.major.y), 1 / n, 1e-6f);
  EXPECT_GT(skew.major.x * skew.major.y, 0);
  // Perpendicular diameters are the axes; a disc has both widths equal.
  const FootprintAxes tall = principal_axes({{0.1f, 0}, {0, -0.4f}});
  EXPECT_FLOAT_EQ(tall.major_width, 0.4f);
  EXPECT_FLOAT_EQ(tall.minor_width, 0.1f);
  EXPECT_FLOAT_EQ(std::abs(tall.major.y), 1.0f);
  const FootprintAxes disc = principal_axes({{0.3f * 0.6f, 0.3f * 0.8f}, {-0.3f * 0.8f, 0.3f * 0.6f}});
  EXPECT_NEAR(disc.major_width, 0.3f, 1e-6f);
  EXPECT_NEAR(disc.minor_width, 0.3f, 1e-6f);
  EXPECT_EQ(principal_axes({{0, 0}, {0, 0}}).major_width, 0.0f);
}

// The footprint in texture coordinates of a cone `width` wide meeting the square (uv = world (x, -y)
// / tile) at the origin, coming in at `incidence_deg` from the normal, from the direction of -y.
FootprintAxes plane_footprint(float incidence_deg, float width, float tile) {
  SceneDesc scene;
  scene.objects.push_back(
      test::model_object(test::square_model(10, tile, test::rough_dielectric({1, 1, 1}))));
  const EmbreeScene geometry(scene, {});
  const float a = incidence_deg * kDeg;
  const Vec3 d{0, std::sin(a), -std::cos(a)};
  const auto hit = geometry.intersect({Vec3{0, 0, 0} - d * 3.0f, d});
  EXPECT_TRUE(hit.has_value());
  if (!hit) return {};
  const RayCone cone{width, 0};
  return principal_axes(uv_footprint(*hit, cone.surface_footprint(d, hit->normal)));
}

TEST(TextureFootprint, APlaneSeenAtAnAngleGivesAnAxisRatioOfOneOverCos) {
  for (const float incidence : {0.0f, 60.0f, 80.0f}) {
    const FootprintAxes f = plane_footprint(incidence, 0.01f, 0.5f);
    const float expected = 1 / std::cos(incidence * kDeg);
    std::printf("incidence %.0f: axes %.6f x %.6f, ratio %.5f (1/cos %.5f)\n", incidence, f.major_width,
                f.minor_width, f.major_width / f.minor_width, expected);
    EXPECT_NEAR(f.major_width / f.minor_width, expected, 1e-4f * expected) << incidence;
    // The width across the ray is the cone's, in UVs of 2 per unit length.
    EXPECT_NEAR(f.minor_width, 0.02f, 1e-6f) << incidence;
    // The long axis runs along the ray's projection, world y, which is texture v.
    if (incidence > 0) {
      EXPECT_NEAR(std::abs(f.major.y), 1.0f, 1e-5f) << incidence;
    }
  }
}

// Black and white bands 8 texels wide, constant along v (white from x = 8 to 15).
std::shared_ptr<const Texture> bands() {
  return test::make_texture(64, 64, [](int x, int) { return (x / 8) % 2 ? Rgb{1, 1, 1} : Rgb{}; });
}

TEST(TextureFootprint, ARoundFootprintTakesOneTrilinearLookupAtItsLevel) {
  const auto t = bands();
  const Point2 uv{0.3f, 0.41f};
  for (const float s : {0.5f / 64, 3.0f / 64, 11.0f / 64}) {
    const Rgba round = t->sample(uv, UvFootprint{{s, 0}, {0, s}}, kMaxTextureAnisotropy);
    EXPECT_EQ(round.r, t->sample(uv, t->level_for_footprint(s)).r) << s;
    const Rgba turned = t->sample(uv, UvFootprint{{0.6f * s, 0.8f * s}, {-0.8f * s, 0.6f * s}}, 16);
    EXPECT_NEAR(turned.r, round.r, 1e-5f) << s;
  }
}

TEST(TextureFootprint, ALongFootprintKeepsTheContrastAcrossIt) {
  const auto t = bands();
  // In the middle of a white band, a footprint one texel wide and 16 long along the bands: the
  // anisotropic filter stays at level 0, inside the band; one isotropic lookup at level 4 blurs it.
  const Point2 uv{12.0f / 64, 0.5f};
  const UvFootprint along{{1.0f / 64, 0}, {0, 16.0f / 64}};
  EXPECT_FLOAT_EQ(t->sample(uv, along, kMaxTextureAnisotropy).r, 1.0f);
  const float isotropic = t->sample(uv, along, 1).r;
  EXPECT_FLOAT_EQ(isotropic, t->sample(uv, 4.0f).r);
  EXPECT_LT(isotropic, 0.75f);
  // Across the bands the probes average them: 16 texels about the white band's middle reach half
  // into the black bands on either side.
  const UvFootprint across{{16.0f / 64, 0}, {0, 1.0f / 64}};
  EXPECT_NEAR(t->sample(uv, across, kMaxTextureAnisotropy).r, 0.5f, 0.07f);
}

TEST(TextureFootprint, ElongationBeyondTheBoundWidensTheFootprint) {
  const auto t = bands();
  const Point2 uv{0.37f, 0.52f};
  const Rgba thin = t->sample(uv, UvFootprint{{0.5f / 64, 0}, {0, 32.0f / 64}}, 8);
  const Rgba widened = t->sample(uv, UvFootprint{{4.0f / 64, 0}, {0, 32.0f / 64}}, 8);
  EXPECT_EQ(thin.r, widened.r);
}

TEST(TextureFootprint, TheTextureTransformScalesAndTurnsTheFootprint) {
  TextureBinding b = test::bind(bands());
  b.transform.scale = {16, 1};
  b.transform.rotation = 0.5f;
  const Point2 uv{0.02f, 0.3f};
  const float s = 1.0f / 64;
  const Rgba seen = b.sample(uv, UvFootprint{{s, 0}, {0, s}}, kMaxTextureAnisotropy);
  const float c = std::cos(0.5f), n = std::sin(0.5f);
  const UvFootprint mapped{{16 * s * c, -16 * s * n}, {s * n, s * c}};
  EXPECT_EQ(seen.r, b.texture->sample(b.transform.apply(uv), mapped, kMaxTextureAnisotropy).r);
  EXPECT_NE(seen.r, b.texture->sample(b.transform.apply(uv), UvFootprint{{s, 0}, {0, s}}, 16).r);
}

TEST(TextureFootprint, WithoutMipmapsTheLookupIsLevelZero) {
  ModelMaterial m = test::rough_dielectric({1, 1, 1});
  m.base_color = test::bind(bands());
  SurfaceHit hit;
  hit.uv = {7.6f / 64, 0.2f};
  hit.du_dp = {1, 0, 0};
  hit.dv_dp = {0, -1, 0};
  hit.shading_normal = hit.normal = {0, 0, 1};
  const SurfaceFootprint wide{{0.2f, 0, 0}, {0, 0.9f, 0}};
  const float level0 = m.base_color->sample(hit.uv, 0.0f).r;
  EXPECT_EQ(model_surface(m, hit, {wide, false, true}).base_color.x, level0);
  EXPECT_NE(model_surface(m, hit, {wide, true, true}).base_color.x, level0);
}

}  // namespace
}  // namespace lp::render

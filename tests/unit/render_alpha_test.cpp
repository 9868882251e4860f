// Coverage and sidedness of glTF materials in the renderer: alphaMode MASK lets exactly the background
// through where alpha < alphaCutoff, for camera, bounce and shadow rays; BLEND covers a fraction alpha
// of the hits; a single-sided material's back faces are not seen by the camera; COLOR_0 and TEXCOORD_1
// feed the material; KHR_materials_emissive_strength scales the emission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "model_test_scenes.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::lighting;
using test::settings;

constexpr int kSize = 32;
constexpr float kBelow = 0.25f;  // the map's radiance below the horizon, seen through the square

// Sky of radiance 1 above the horizon, kBelow below it.
std::shared_ptr<const EnvMap> sky() {
  return test::make_map(64, [](Vec3 d) { return d.z > 0 ? Rgb{1, 1, 1} : Rgb{kBelow, kBelow, kBelow}; });
}

// The camera straight above the square, which fills the image; image x runs along world +x.
SceneDesc square_scene(const ModelMaterial& material, float camera_z = 3) {
  SceneDesc scene;
  scene.camera.position = {0, 0, camera_z};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_deg = 30;
  scene.objects.push_back(test::model_object(test::square_model(1, 2, material)));
  return scene;
}

Image render(const SceneDesc& scene, int spp = 4, uint64_t seed = 1) {
  return test::render(scene, lighting(LightingMode::EnvMap), settings(kSize, 8, seed), sky(), spp);
}

// A grey rough dielectric whose colour and alpha a test sets.
ModelMaterial grey(float alpha = 1) {
  ModelMaterial m = test::rough_dielectric({0.5f, 0.5f, 0.5f});
  m.base_color_factor.a = alpha;
  return m;
}

double image_mean(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).x;
  return sum / (image.width() * image.height());
}

void expect_same(const Image& a, const Image& b) {
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) ASSERT_EQ(a.at(x, y), b.at(x, y)) << x << ", " << y;
}

// Equal up to float rounding (interpolated vertex attributes of equal values differ in the last bit).
void expect_close(const Image& a, const Image& b) {
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(a.at(x, y)[k], b.at(x, y)[k], 1e-5f * b.at(x, y)[k]) << x << ", " << y;
}

// Every pixel the map's radiance `radiance` exactly.
void expect_background(const Image& a, float radiance = kBelow) {
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      ASSERT_EQ(a.at(x, y), (Rgb{radiance, radiance, radiance})) << x << ", " << y;
}

TEST(RenderAlpha, AMaskedTexelLetsExactlyTheBackgroundThrough) {
  // Left half of the texture alpha 0, right half alpha 1; u = (x + 1) / 2 across the square.
  ModelMaterial masked = grey();
  masked.alpha_mode = AlphaMode::Mask;
  masked.base_color = test::bind(test::make_rgba_texture(8, 1, [](int x, int) {
    return Rgba{1, 1, 1, x < 4 ? 0.0f : 1.0f};
  }));
  masked.base_color->transform.offset = {0.5f, 0};
  masked.base_color->sampler = {WrapMode::ClampToEdge, WrapMode::ClampToEdge};
  ModelMaterial opaque = masked;
  opaque.alpha_mode = AlphaMode::Opaque;  // ignores alpha, as glTF says
  const Image a = render(square_scene(masked)), b = render(square_scene(opaque));
  int background = 0, surface = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (x == kSize / 2 - 1 || x == kSize / 2) continue;  // next to the boundary, u = 0.5
      if (x < kSize / 2) {
        ASSERT_EQ(a.at(x, y), (Rgb{kBelow, kBelow, kBelow})) << x << ", " << y;
        ++background;
      } else {
        ASSERT_EQ(a.at(x, y), b.at(x, y)) << x << ", " << y;
        ASSERT_GT(std::abs(b.at(x, y).x - kBelow), 0.05f);
        ++surface;
      }
    }
  EXPECT_EQ(background, surface);
}

TEST(RenderAlpha, MaskCutoffOnBothSidesOfAlpha) {
  // alpha = factor 0.8 x texture 0.5 x COLOR_0 0.75 = 0.3.
  ModelMaterial m = grey(0.8f);
  m.alpha_mode = AlphaMode::Mask;
  m.base_color = test::bind(test::make_rgba_texture(1, 1, [](int, int) { return Rgba{1, 1, 1, 0.5f}; }));
  const auto with_colour = [](const ModelMaterial& material) {
    SceneDesc scene = square_scene(material);
    Model model = *std::get<MeshObject>(scene.objects[0].shape).model;
    model.colors.assign(model.vertex_count(), Rgba{1, 1, 1, 0.75f});
    scene.objects[0] = test::model_object(std::move(model));
    return scene;
  };
  ModelMaterial opaque = m;
  opaque.alpha_mode = AlphaMode::Opaque;
  const Image surface = render(with_colour(opaque));
  m.alpha_cutoff = 0.29f;
  expect_same(render(with_colour(m)), surface);
  m.alpha_cutoff = 0.31f;
  expect_background(render(with_colour(m)));
  m.alpha_cutoff = 0.5f;  // the default: alpha 0.3 is cut
  expect_background(render(with_colour(m)));
}

TEST(RenderAlpha, BlendCoversTheFractionAlphaOfTheHits) {
  // A pixel's expected radiance is 0.3 surface + 0.7 background. Over 32 x 32 pixels at 64 spp the
  // coverage's own noise is sqrt(0.21 / 65536) = 0.0018 of (surface - background); with the shading's
  // noise the measured deviation is well inside 1%.
  ModelMaterial blend = grey(0.3f);
  blend.alpha_mode = AlphaMode::Blend;
  ModelMaterial opaque = grey();
  const double s = image_mean(render(square_scene(opaque), 64));
  const double mixed = image_mean(render(square_scene(blend), 64));
  const double expected = 0.3 * s + 0.7 * kBelow;
  std::printf("blend alpha 0.3: mean %.5f, expected %.5f (surface %.5f, background %.2f)\n", mixed, expected,
              s, kBelow);
  EXPECT_NEAR(mixed, expected, 0.01 * std::abs(s - kBelow));
  // The same seed gives the same image.
  expect_same(render(square_scene(blend), 4, 7), render(square_scene(blend), 4, 7));
}

// A diffuse floor under a square held over it; the camera looks at the floor from below the square's
// height, so only bounce and shadow rays can meet the square.
SceneDesc shadowed_floor(std::optional<ModelMaterial> roof) {
  SceneDesc scene;
  scene.camera.position = {0, -3, 0.5f};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.fov_deg = 30;
  scene.objects.push_back({PlaneObject{{0, 0, 0}, {0, 0, 1}}, DiffuseMaterial{{0.8f, 0.8f, 0.8f}}});
  if (roof) {
    Model m = test::square_model(2, 2, *roof);
    for (Vec3& p : m.positions) p.z = 1;
    scene.objects.push_back(test::model_object(std::move(m)));
  }
  return scene;
}

TEST(RenderAlpha, AMaskedOutSquareCastsNoShadowAndReflectsNothing) {
  ModelMaterial cut = grey(0);
  cut.alpha_mode = AlphaMode::Mask;
  const Image none = render(shadowed_floor(std::nullopt), 8);
  expect_same(render(shadowed_floor(cut), 8), none);
  // The same square opaque darkens the floor under it.
  const Image shadow = render(shadowed_floor(grey()), 8);
  EXPECT_LT(image_mean(shadow), 0.8 * image_mean(none));
}

TEST(RenderAlpha, ABlendSquaresShadowPassesTheFractionOneMinusAlpha) {
  // Seen from the centre of the floor, the square (half-size 2 at height 1) covers the sky from the
  // zenith down to 26.6 degrees of elevation; the shadowed irradiance is (1 - alpha) of what it takes.
  // A black square, so that little light reflects between it and the floor: the floor's radiance is then
  // close to linear in the coverage.
  ModelMaterial black = test::rough_dielectric({0, 0, 0});
  ModelMaterial blend = black;
  blend.base_color_factor.a = 0.3f;
  blend.alpha_mode = AlphaMode::Blend;
  const double none = image_mean(render(shadowed_floor(std::nullopt), 64));
  const double opaque = image_mean(render(shadowed_floor(black), 64));
  const double half = image_mean(render(shadowed_floor(blend), 64));
  const double expected = 0.3 * opaque + 0.7 * none;
  std::printf("blend shadow: none %.5f, opaque %.5f, blend %.5f, expected %.5f\n", none, opaque, half,
              expected);
  EXPECT_NEAR(half, expected, 0.02 * (none - opaque));
}

TEST(RenderAlpha, ASingleSidedSquaresBackIsNotSeenByTheCamera) {
  ModelMaterial single = grey();
  single.double_sided = false;
  ModelMaterial both = grey();
  // From above (its front): the same either way.
  expect_same(render(square_scene(single)), render(square_scene(both)));
  // From below (its back): the map's radiance above, exactly; double-sided, the square.
  expect_background(render(square_scene(single, -3)), 1.0f);
  const Image seen = render(square_scene(both, -3));
  EXPECT_LT(image_mean(seen), 0.9);
}

TEST(RenderAlpha, EmissiveStrengthScalesTheEmission) {
  ModelMaterial m = grey();
  m.emissive_factor = {0.2f, 0.3f, 0.4f};
  const auto emitted = [&](float strength) {
    m.emissive_strength = strength;
    const Image lit = render(square_scene(m));
    ModelMaterial dark = m;
    dark.emissive_factor = {};
    const Image unlit = render(square_scene(dark));
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) sum += lit.at(x, y).z - unlit.at(x, y).z;
    return sum / (kSize * kSize);
  };
  const double one = emitted(1), five = emitted(5);
  std::printf("emission: strength 1 %.6f, strength 5 %.6f, ratio %.6f\n", one, five, five / one);
  EXPECT_NEAR(one, 0.4, 1e-5);
  EXPECT_NEAR(five / one, 5.0, 1e-5);
}

// The square with per-vertex colours `color`.
SceneDesc coloured_square(const ModelMaterial& material, Rgba color) {
  SceneDesc scene = square_scene(material);
  Model model = *std::get<MeshObject>(scene.objects[0].shape).model;
  model.colors.assign(model.vertex_count(), color);
  scene.objects[0] = test::model_object(std::move(model));
  return scene;
}

TEST(RenderAlpha, VertexColoursMultiplyTheBaseColour) {
  ModelMaterial white = test::rough_dielectric({1, 1, 1});
  ModelMaterial tinted = test::rough_dielectric({0.5f, 0.25f, 1});
  expect_close(render(coloured_square(white, {0.5f, 0.25f, 1, 1})), render(square_scene(tinted)));
}

TEST(RenderAlpha, VertexColourHalvesAWhiteDiffuseInTheFurnace) {
  // A white rough dielectric whose COLOR_0 is 0.5 renders as one of base colour 0.5 does, sample for
  // sample, and a white one stays at 1.
  SceneDesc furnace = coloured_square(test::rough_dielectric({1, 1, 1}), {0.5f, 0.5f, 0.5f, 1});
  SceneDesc half = square_scene(test::rough_dielectric({0.5f, 0.5f, 0.5f}));
  const auto constant = test::constant_map(1.0f);
  const auto run = [&](const SceneDesc& s) {
    return test::render(s, lighting(LightingMode::EnvMap), settings(kSize), constant, 64);
  };
  const Image a = run(furnace), b = run(half);
  expect_close(a, b);
  const double mean = image_mean(a);
  std::printf("furnace, COLOR_0 0.5 on white: %.5f\n", mean);
  EXPECT_GT(mean, 0.5);  // the coat reflects on top of the base's 0.5 of the rest
  EXPECT_LT(mean, 0.6);
}

TEST(RenderAlpha, ATextureOnTheSecondSetSamplesTEXCOORD_1) {
  ModelMaterial m = grey();
  m.base_color = test::bind(test::make_texture(4, 4, [](int x, int y) {
    return Rgb{float(x) / 3, float(y) / 3, 1};
  }));
  const SceneDesc first = square_scene(m);
  // The same coordinates as the second set, the first set constant.
  Model model = *std::get<MeshObject>(first.objects[0].shape).model;
  model.uvs1 = model.uvs;
  for (Point2& uv : model.uvs) uv = {0.1f, 0.9f};
  model.materials[0].base_color->tex_coord = 1;
  SceneDesc second = first;
  second.objects[0] = test::model_object(std::move(model));
  expect_same(render(second), render(first));
}

}  // namespace
}  // namespace lp::render

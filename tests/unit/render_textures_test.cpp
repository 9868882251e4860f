// Textured models in the renderer: base-colour textures filtered over ray cones' footprints, mipmaps
// against aliasing, anisotropic footprints at grazing angles, tangent-space normal maps (a flat map
// changes nothing, a tilted one shades like a tilted plane, none gains energy, mirrored UVs shade like
// unmirrored ones). The Khronos samples on screen: render_gltf_samples_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/core/constants.hpp"
#include "engine/model/mesh_part.hpp"
#include "engine/model/model_loader.hpp"
#include "model_test_scenes.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::constant_map;
using test::lighting;
using test::settings;

Camera look(Vec3 from, Vec3 at, float fov = 40) {
  Camera c;
  c.position = from;
  c.look_at = at;
  c.up = {0, 0, 1};
  if (std::abs(at.x - from.x) < 1e-6f && std::abs(at.y - from.y) < 1e-6f) c.up = {0, 1, 0};
  c.fov_deg = fov;
  return c;
}

double channel_mean(const Image& image, int y0, int y1) {
  double sum = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width(); ++x) {
      sum += image.at(x, y).x;
      ++n;
    }
  return sum / n;
}

// The variance of each row about its own mean, averaged over rows y0..y1-1 (rows differ in distance).
double row_variance(const Image& image, int y0, int y1) {
  double total = 0;
  for (int y = y0; y < y1; ++y) {
    const double mean = channel_mean(image, y, y + 1);
    double sq = 0;
    for (int x = 0; x < image.width(); ++x) {
      const double d = image.at(x, y).x - mean;
      sq += d * d;
    }
    total += sq / image.width();
  }
  return total / (y1 - y0);
}

TEST(RenderTextures, MipmapsQuietTheFarRegionOfAGrazingCheckerboard) {
  ModelMaterial material = test::rough_dielectric({1, 1, 1});
  material.base_color = test::bind(test::make_texture(64, 64, [](int x, int y) {
    return ((x / 8 + y / 8) % 2) ? Rgb{1, 1, 1} : Rgb{};
  }));
  SceneDesc scene;
  scene.camera = look({0, 0, 0.5f}, {0, 20, 0.1f}, 40);
  scene.objects.push_back(test::model_object(test::square_model(1000, 1, material)));
  RenderSettings on = settings(96, 1), off = on;
  off.mipmaps = false;
  // The far region: ten rows below the horizon, where a pixel spans several checker cells (of 1/8).
  const Image a = test::render(scene, lighting(LightingMode::EnvMap), on, constant_map(1.0f), 2);
  const Image b = test::render(scene, lighting(LightingMode::EnvMap), off, constant_map(1.0f), 2);
  const float tilt = std::atan2(0.4f, 20.0f), half_fov = 20 * kPiF / 180;
  const int horizon = int(std::ceil(48 * (1 - std::tan(tilt) / std::tan(half_fov))));
  const int y0 = horizon + 1, y1 = horizon + 11;
  const double var_on = row_variance(a, y0, y1), var_off = row_variance(b, y0, y1);
  std::printf(
      "grazing checkerboard, rows %d-%d: variance mipmaps on %.5f, off %.5f, ratio %.1f; means %.3f %.3f\n",
      y0, y1, var_on, var_off, var_off / var_on, channel_mean(a, y0, y1), channel_mean(b, y0, y1));
  EXPECT_GT(var_off / var_on, 3.0);  // measured 17.7 (path-tracing noise remains with mipmaps on)
  EXPECT_NEAR(channel_mean(a, y0, y1), channel_mean(b, y0, y1), 0.1 * channel_mean(b, y0, y1));
}

SceneDesc normal_mapped_square(std::optional<TextureBinding> normal_map, Vec3 rotate_deg = {}) {
  ModelMaterial material = test::rough_dielectric({0.8f, 0.8f, 0.8f});
  material.normal = std::move(normal_map);
  SceneDesc scene;
  scene.camera = look({0.3f, -0.2f, 3}, {0, 0, 0}, 30);
  scene.objects.push_back(test::model_object(test::square_model(3, 1, material), rotate_deg));
  return scene;
}

// Sky above the horizon, brighter towards +x; black below.
std::shared_ptr<const EnvMap> half_sky() {
  return test::make_map(128, [](Vec3 d) {
    const float v = d.z > 0 ? 1.0f + d.x : 0.0f;
    return Rgb{v, v, v};
  });
}

// relMSE over rows y0..y1-1: mean((a - b)^2) / mean(b)^2.
double rel_mse(const Image& a, const Image& b, int y0, int y1) {
  double sq = 0, sum = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < a.width(); ++x) {
      const double d = a.at(x, y).x - b.at(x, y).x;
      sq += d * d;
      sum += b.at(x, y).x;
      ++n;
    }
  const double mean = sum / n;
  return sq / n / (mean * mean);
}

// An emissive plane seen at grazing incidence, without bounces: each pixel shows the texture filtered
// over its footprint, which many samples at level 0 (spread over the pixel) converge to. The texture
// has wide bands across the view (u) and fine stripes along it (v, 0.25 units apart in the world). One
// isotropic level blurs the bands as much as the stripes; level 0 keeps the bands but aliases the
// stripes; the anisotropic footprint keeps one and averages the other.
TEST(RenderTextures, AnisotropicFilteringKeepsGrazingBandsWithoutAliasingTheirStripes) {
  ModelMaterial material = test::rough_dielectric({0, 0, 0});
  material.emissive_factor = {1, 1, 1};
  material.emissive = test::bind(test::make_texture(64, 64, [](int x, int y) {
    const float v = 0.5f * float((x / 16) % 2) + 0.5f * float((y / 2) % 2);
    return Rgb{v, v, v};
  }));
  SceneDesc scene;
  scene.camera = look({0, 0, 0.5f}, {0, 20, 0.1f}, 40);
  scene.objects.push_back(test::model_object(test::square_model(1000, 4, material)));
  const int size = 64;
  RenderSettings anisotropic = settings(size, 0), isotropic = anisotropic, level0 = anisotropic;
  isotropic.texture_anisotropy = 1;
  level0.mipmaps = false;
  const auto map = constant_map(0.25f);
  const Lighting light = lighting(LightingMode::EnvMap);
  const Image reference = test::render(scene, light, level0, map, 1024);
  const Image a = test::render(scene, light, anisotropic, map, 1);
  const Image i = test::render(scene, light, isotropic, map, 1);
  const Image z = test::render(scene, light, level0, map, 1);
  // The far rows, from two below the horizon: the ground 14 to 3 units away, where a pixel spans more
  // than a stripe along the view (nearer, all three differ from the reference by the same one-sample
  // noise at the bands' edges).
  const float tilt = std::atan2(0.4f, 20.0f), half_fov = 20 * kPiF / 180;
  const int y0 = int(std::ceil(0.5f * size * (1 - std::tan(tilt) / std::tan(half_fov)))) + 2, y1 = y0 + 12;
  const double err_a = rel_mse(a, reference, y0, y1), err_i = rel_mse(i, reference, y0, y1),
               err_z = rel_mse(z, reference, y0, y1);
  const double var_ref = row_variance(reference, y0, y1), var_a = row_variance(a, y0, y1),
               var_i = row_variance(i, y0, y1);
  std::printf(
      "grazing bands, rows %d-%d: relMSE to 1024 spp at level 0: anisotropic %.4f, isotropic %.4f, "
      "level 0 at 1 spp %.4f; row variance reference %.4f, anisotropic %.4f, isotropic %.4f\n",
      y0, y1, err_a, err_i, err_z, var_ref, var_a, var_i);
  EXPECT_LT(err_a, 0.5 * err_i);  // measured 0.0196 against 0.0603
  EXPECT_LT(err_a, 0.2 * err_z);  // against 0.1888
  // The bands' contrast across each row: the reference's (0.0529), which the isotropic level halves.
  EXPECT_LT(std::abs(var_a - var_ref), 0.25 * std::abs(var_i - var_ref));
}

TEST(RenderTextures, FlatNormalMapRendersExactlyLikeNone) {
  const auto exact = test::make_texture(4, 4, [](int, int) { return Rgb{0.5f, 0.5f, 1}; });
  const auto eight_bit = test::make_texture(4, 4, [](int, int) {
    return Rgb{128 / 255.0f, 128 / 255.0f, 1};
  });
  const Image none = test::render(normal_mapped_square(std::nullopt), lighting(LightingMode::EnvMap),
                                  settings(32), half_sky(), 4);
  for (const auto& map : {exact, eight_bit}) {
    const Image flat = test::render(normal_mapped_square(test::bind(map)), lighting(LightingMode::EnvMap),
                                    settings(32), half_sky(), 4);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) ASSERT_EQ(flat.at(x, y), none.at(x, y)) << x << ", " << y;
  }
}

TEST(RenderTextures, TiltedNormalMapShadesLikeATiltedPlane) {
  constexpr float kTiltDeg = 20;
  const float a = kTiltDeg * kPiF / 180;
  // Tangent space x is world +x here: a normal leaning to +x, as the square turned about y by +20 deg.
  const Rgb texel{0.5f * (std::sin(a) + 1), 0.5f, 0.5f * (std::cos(a) + 1)};
  const auto map = test::make_texture(2, 2, [&](int, int) { return texel; });
  SceneDesc mapped = normal_mapped_square(test::bind(map));
  SceneDesc tilted = normal_mapped_square(std::nullopt, {0, kTiltDeg, 0});
  SceneDesc flat = normal_mapped_square(std::nullopt);
  for (SceneDesc* s : {&mapped, &tilted, &flat}) s->camera = look({0, 0, 3}, {0, 0, 0}, 10);
  const auto render = [](const SceneDesc& s) {
    return test::render(s, lighting(LightingMode::EnvMap), settings(16), half_sky(), 256);
  };
  const double m = channel_mean(render(mapped), 0, 16), t = channel_mean(render(tilted), 0, 16),
               f = channel_mean(render(flat), 0, 16);
  std::printf("tilted normal map %.4f, tilted plane %.4f, flat plane %.4f\n", m, t, f);
  EXPECT_NEAR(m, t, 0.01 * t);
  EXPECT_GT(std::abs(m - f), 0.05 * f);  // the tilt is visible
}

// The square [-1, 1]^2 at z = 0 as two triangles sharing the diagonal from (-1, -1) to (1, 1), completed
// as the loaders complete a mesh (tangents generated). Lower-right triangle: u = (x + 1) / 2,
// v = (1 - y) / 2. Upper-left: the same, or (mirrored) its UVs reflected across the diagonal
// (u = (y + 1) / 2, v = (1 - x) / 2), so that the diagonal's two vertices are shared by triangles of
// opposite UV handedness.
Model diagonal_square(bool mirrored, const ModelMaterial& material) {
  const auto uv = [](float x, float y) { return Point2{(x + 1) / 2, (1 - y) / 2}; };
  MeshPart part;
  part.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  part.normals.assign(4, Vec3{0, 0, 1});
  part.uvs = {uv(-1, -1), uv(1, -1), uv(1, 1), mirrored ? uv(1, -1) : uv(-1, 1)};
  part.indices = {0, 1, 2, 0, 2, 3};
  part.triangle_materials = {0, 0};
  complete_part(part);
  Model m;
  append_part(m, part, Mat4{});
  m.materials = {material};
  return m;
}

// Mean of the red channel over the pixels (x, y) of a square image with s_min <= x + y + 1 - width <=
// s_max. Seen from above with +y up the image, s = 0 is the world diagonal x = y, s >= 2 lies wholly on
// its lower-right side, s <= -2 on the upper-left one, and |s| <= 1 straddles it.
double diagonal_band_mean(const Image& image, int s_min, int s_max) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const int s = x + y + 1 - image.width();
      if (s < s_min || s > s_max) continue;
      sum += image.at(x, y).x;
      ++n;
    }
  return sum / n;
}

TEST(RenderTextures, MirroredUvsShadeAConstantTiltWithoutASeam) {
  // A tangent-space normal tilted 20 degrees towards (t + b) / sqrt(2): on the lower-right triangle
  // (t = +x, b = +y) it leans towards world (1, 1, 0), and on the mirrored upper-left one (t = +y,
  // b = +x, w = -1) towards the same (1, 1, 0). Averaged tangents at the shared diagonal would give no
  // frame there (+x and +y summed, bitangents opposite) and turn the normal elsewhere near the seam.
  const float a = 20 * kPiF / 180, lean = std::sin(a) / std::sqrt(2.0f);
  const Rgb texel{0.5f * (lean + 1), 0.5f * (lean + 1), 0.5f * (std::cos(a) + 1)};
  ModelMaterial material = test::rough_dielectric({0.8f, 0.8f, 0.8f});
  material.normal = test::bind(test::make_texture(2, 2, [&](int, int) { return texel; }));
  ModelMaterial unmapped = material;
  unmapped.normal.reset();
  // A sky brighter towards +x, and less so towards +y, so that any turn of the normal shows.
  const auto sky = test::make_map(128, [](Vec3 d) {
    const float v = d.z > 0 ? 1.0f + d.x + 0.5f * d.y : 0.0f;
    return Rgb{v, v, v};
  });
  const auto render = [&](Model m) {
    SceneDesc scene;
    scene.camera = look({0, 0, 3}, {0, 0, 0}, 10);
    scene.objects.push_back(test::model_object(std::move(m)));
    return test::render(scene, lighting(LightingMode::EnvMap), settings(32), sky, 128);
  };
  const Image mirrored = render(diagonal_square(true, material));
  const Image upright = render(diagonal_square(false, material));
  const Image flat = render(diagonal_square(false, unmapped));
  // Lower-right half, the band along the diagonal, upper-left half.
  const std::pair<int, int> regions[] = {{2, 32}, {-1, 1}, {-32, -2}};
  for (const auto& [lo, hi] : regions) {
    const double m = diagonal_band_mean(mirrored, lo, hi), u = diagonal_band_mean(upright, lo, hi),
                 f = diagonal_band_mean(flat, lo, hi);
    std::printf("diagonal band [%d, %d]: mirrored UVs %.4f, unmirrored %.4f, no normal map %.4f\n", lo, hi, m,
                u, f);
    EXPECT_NEAR(m, u, 0.005 * u) << lo << ".." << hi;
    EXPECT_GT(std::abs(u - f), 0.05 * f) << lo << ".." << hi;  // the tilt is visible
  }
  // Both halves shade as one tilted plane (they differ only in the view direction, by under 2 degrees).
  EXPECT_NEAR(diagonal_band_mean(mirrored, 2, 32), diagonal_band_mean(mirrored, -32, -2),
              0.01 * diagonal_band_mean(mirrored, 2, 32));
}

TEST(RenderTextures, NormalMappedWhiteSquareInAFurnaceStaysNearOne) {
  // Bumps of 14 degrees rms, 21 at most. The guard discards light below the geometric surface: a
  // cosine lobe tilted by t loses (1 - cos t) / 2 of itself there, 1.6% averaged over this map; the
  // white coated base itself reflects everything (bsdf_plastic.hpp). Measured: 0.993. Nothing can add
  // energy: the render stays <= 1.
  const auto bumps = test::make_texture(32, 32, [](int x, int y) {
    const float nx = 0.25f * std::sin(float(x) * 0.6f), ny = 0.25f * std::cos(float(y) * 0.45f);
    const float nz = std::sqrt(1 - nx * nx - ny * ny);
    return Rgb{0.5f * (nx + 1), 0.5f * (ny + 1), 0.5f * (nz + 1)};
  });
  ModelMaterial white = test::rough_dielectric({1, 1, 1});
  white.base_color = test::bind(test::make_texture(8, 8, [](int, int) { return Rgb{1, 1, 1}; }));
  white.normal = test::bind(bumps);
  SceneDesc scene;
  scene.camera = look({0, -1, 3}, {0, 0, 0}, 20);
  scene.objects.push_back(test::model_object(test::square_model(3, 0.5f, white)));
  const Image image =
      test::render(scene, lighting(LightingMode::EnvMap), settings(24, 1), constant_map(1.0f), 64);
  const double mean = channel_mean(image, 0, 24);
  double max_pixel = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) max_pixel = std::max(max_pixel, double(image.at(x, y).x));
  std::printf("normal-mapped white furnace: mean %.4f, max pixel %.4f\n", mean, max_pixel);
  EXPECT_NEAR(mean, 1.0, 0.016);
  EXPECT_LT(mean, 1.0 + 2e-3);
}

}  // namespace
}  // namespace lp::render

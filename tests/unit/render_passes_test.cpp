// Backgrounds, the auxiliary passes, the shadow catcher and the indirect clamp against analytic answers:
// a transparent corner has alpha and colour exactly 0, a sphere's pixels alpha 1; a white diffuse sphere's
// albedo pass is 1; the normal pass is (p - c) / r and the depth pass the distance to the sphere along
// each pixel's ray; a shadow catcher on a white map leaves the background exactly where no sample is
// shadowed and carries the shadow in alpha, and a mirror catcher the sphere's reflection; the clamp lowers
// indirect light and leaves direct light alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/render/camera.hpp"
#include "engine/render/film.hpp"
#include "engine/render/partial_film_codec.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::lighting;
using test::settings;

constexpr int kSize = 33;  // odd: the centre pixel's centre is on the optical axis
constexpr float kRadius = 1;

SceneObject white_sphere(Vec3 center = {0, 0, 0}) {
  return {SphereObject{center, kRadius}, DiffuseMaterial{{1, 1, 1}}};
}

// The camera on -y at distance 4 from the origin, looking at it.
SceneDesc sphere_scene() {
  SceneDesc scene;
  scene.objects.push_back(white_sphere());
  return scene;
}

struct Rendered {
  Image color;
  std::optional<Image> albedo, normal, depth, alpha;
};

Rendered render(const SceneDesc& scene, RenderSettings s, int spp, float map_radiance = 1,
                LightingMode mode = LightingMode::EnvMap) {
  s.spp = spp;
  Renderer renderer(scene, lighting(mode), s, test::constant_map(map_radiance));
  std::atomic<bool> cancel{false};
  renderer.render_pass(spp, cancel, {});
  Rendered out{renderer.image(), {}, {}, {}, {}};
  if (s.passes.has(AuxPass::Albedo)) out.albedo = renderer.image(AuxPass::Albedo);
  if (s.passes.has(AuxPass::Normal)) out.normal = renderer.image(AuxPass::Normal);
  if (s.passes.has(AuxPass::Depth)) out.depth = renderer.image(AuxPass::Depth);
  if (s.passes.has(AuxPass::Alpha)) out.alpha = renderer.image(AuxPass::Alpha);
  return out;
}

RenderSettings with_passes(PassSet passes, BackgroundMode background = BackgroundMode::Map) {
  RenderSettings s = settings(kSize);
  s.passes = passes;
  s.background.mode = background;
  return s;
}

// The distance along pixel (x, y)'s central ray to the sphere at c, if it meets it.
std::optional<float> sphere_distance(const PerspectiveCamera& camera, int x, int y, Vec3 c) {
  const Ray ray = camera.generate(float(x) + 0.5f, float(y) + 0.5f);
  const Vec3 oc = ray.origin - c;
  const float b = dot(oc, ray.direction), disc = b * b - (dot(oc, oc) - kRadius * kRadius);
  if (disc < 0) return std::nullopt;
  return -b - std::sqrt(disc);
}

TEST(RenderPasses, TransparentCornerIsZeroAndTheSphereCoversItsPixels) {
  const Rendered r = render(sphere_scene(), with_passes({AuxPass::Alpha}, BackgroundMode::Transparent), 16);
  for (const auto& [x, y] : {std::pair{0, 0}, {kSize - 1, 0}, {0, kSize - 1}, {kSize - 1, kSize - 1}}) {
    EXPECT_EQ(r.alpha->at(x, y).x, 0.0f) << x << "," << y;
    EXPECT_EQ(r.color.at(x, y), (Rgb{0, 0, 0})) << x << "," << y;
  }
  const int c = kSize / 2;
  EXPECT_EQ(r.alpha->at(c, c).x, 1.0f);
  EXPECT_GT(r.color.at(c, c).x, 0.1f);  // the sphere is lit by the map it no longer shows
}

TEST(RenderPasses, ColourBackgroundIsSeenByEscapingCameraRaysOnly) {
  RenderSettings s = with_passes({AuxPass::Alpha}, BackgroundMode::Color);
  s.background.color = {0.25f, 0.5f, 0.75f};
  const Rendered r = render(sphere_scene(), s, 16);
  EXPECT_EQ(r.color.at(0, 0), s.background.color);
  EXPECT_EQ(r.alpha->at(0, 0).x, 0.0f);
  // The sphere is lit by the white map, not by the colour: grey, at its furnace value 1.
  EXPECT_NEAR(test::sphere_mean(r.color), 1.0, 0.02);
  const Rgb centre = r.color.at(kSize / 2, kSize / 2);
  EXPECT_EQ(centre.x, centre.z);
}

TEST(RenderPasses, AlbedoOfAWhiteDiffuseSphereIsOne) {
  const Rendered r = render(sphere_scene(), with_passes({AuxPass::Albedo}), 4);
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (test::on_preset_sphere(x, y, kSize)) {
        const Rgb a = r.albedo->at(x, y);
        ASSERT_NEAR(a.x, 1.0f, 1e-5f) << x << "," << y;
        ASSERT_NEAR(a.y, 1.0f, 1e-5f);
        ASSERT_NEAR(a.z, 1.0f, 1e-5f);
        ++checked;
      }
  EXPECT_GT(checked, 300);
  EXPECT_EQ(r.albedo->at(0, 0), (Rgb{0, 0, 0}));  // an escaped ray has none
}

TEST(RenderPasses, NormalAndDepthOfASphereAreItsGeometry) {
  const Vec3 c{0.4f, 0.3f, -0.2f};  // off the axis, so each pixel's normal differs
  SceneDesc scene;
  scene.objects.push_back(white_sphere(c));
  const Rendered r = render(scene, with_passes({AuxPass::Normal, AuxPass::Depth}), 16);
  const PerspectiveCamera camera(scene.camera, kSize, kSize);
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto t = sphere_distance(camera, x, y, c);
      // Pixels whose whole footprint is on the sphere: the central ray at least a pixel inside its rim.
      const auto t_neighbours = {sphere_distance(camera, x - 1, y, c), sphere_distance(camera, x + 1, y, c),
                                 sphere_distance(camera, x, y - 1, c), sphere_distance(camera, x, y + 1, c)};
      if (!t || std::any_of(t_neighbours.begin(), t_neighbours.end(), [](auto v) { return !v; })) {
        const bool near_sphere =
            t || std::any_of(t_neighbours.begin(), t_neighbours.end(), [](auto v) { return v.has_value(); });
        if (!near_sphere) {
          EXPECT_TRUE(std::isinf(r.depth->at(x, y).x)) << x << "," << y;
        }
        continue;
      }
      const Ray ray = camera.generate(float(x) + 0.5f, float(y) + 0.5f);
      const Vec3 expected = (ray.origin + ray.direction * *t - c) / kRadius;
      const Vec3 n = r.normal->at(x, y);
      ASSERT_NEAR(n.x, expected.x, 0.03f) << x << "," << y;
      ASSERT_NEAR(n.y, expected.y, 0.03f) << x << "," << y;
      ASSERT_NEAR(n.z, expected.z, 0.03f) << x << "," << y;
      ASSERT_NEAR(r.depth->at(x, y).x, *t, 0.02f) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 200);
  // The centre pixel looks at the sphere's nearest point when the sphere is on the axis.
  const Rendered centred = render(sphere_scene(), with_passes({AuxPass::Normal, AuxPass::Depth}), 16);
  const int m = kSize / 2;
  EXPECT_NEAR(centred.depth->at(m, m).x, 4.0f - kRadius, 1e-3f);
  EXPECT_NEAR(centred.normal->at(m, m).y, -1.0f, 1e-3f);
  EXPECT_TRUE(std::isinf(centred.depth->at(0, 0).x));
  EXPECT_EQ(centred.normal->at(0, 0), (Rgb{0, 0, 0}));
}

// A diffuse sphere resting on a shadow catcher placed under it (no height: its lowest z), seen from
// above at an angle, on a white map.
SceneDesc catcher_scene() {
  SceneDesc scene;
  scene.objects.push_back({SphereObject{{0, 0, 1}, kRadius}, DiffuseMaterial{{0.8f, 0.8f, 0.8f}}});
  SceneObject ground{PlaneObject{}, DiffuseMaterial{}};
  ground.ground = Ground{std::nullopt, true};
  scene.objects.push_back(ground);
  scene.camera.position = {0, -9, 6};
  scene.camera.look_at = {0, 0, 0.5f};
  scene.camera.fov_deg = 60;
  return scene;
}

TEST(RenderPasses, ShadowCatcherKeepsTheBackgroundOutsideItsShadowAndCarriesTheShadowInAlpha) {
  constexpr int kCatcherSize = 48, kSpp = 16;
  const SceneDesc scene = catcher_scene();
  RenderSettings s = settings(kCatcherSize);
  s.passes = {AuxPass::Alpha};
  const Rendered on_map = render(scene, s, kSpp);
  s.background.mode = BackgroundMode::Transparent;
  const Rendered cut_out = render(scene, s, kSpp);

  const PerspectiveCamera camera(scene.camera, kCatcherSize, kCatcherSize);
  int far_exact = 0, far = 0, near = 0;
  double near_sum = 0;
  for (int y = 0; y < kCatcherSize; ++y)
    for (int x = 0; x < kCatcherSize; ++x) {
      // Pixels whose footprint is all on the ground, off the sphere.
      bool on_ground = true;
      float reach = 0;
      for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}}) {
        const Ray ray = camera.generate(float(x) + dx, float(y) + dy);
        const Vec3 oc = ray.origin - Vec3{0, 0, 1};
        const float b = dot(oc, ray.direction);
        const bool hits_sphere = b * b - (dot(oc, oc) - 1) >= 0 && -b > 0;
        const float t = -ray.origin.z / ray.direction.z;
        const Vec3 p = ray.origin + ray.direction * t;
        on_ground = on_ground && !hits_sphere && ray.direction.z < 0;
        reach = std::max(reach, std::hypot(p.x, p.y));
      }
      if (!on_ground) continue;
      const float value = on_map.color.at(x, y).x, alpha = cut_out.alpha->at(x, y).x;
      const float bounced = cut_out.color.at(x, y).x;  // the sphere's light, premultiplied
      EXPECT_EQ(on_map.alpha->at(x, y).x, alpha);
      // The background behind, darkened by the shadow's opacity, plus the light the sphere bounces.
      EXPECT_NEAR(value, 1.0f - alpha + bounced, 1e-5f) << x << "," << y;
      if (alpha == 0.0f) {  // no sample shadowed, none met the sphere: the background exactly
        EXPECT_EQ(value, 1.0f) << x << "," << y;
        EXPECT_EQ(bounced, 0.0f) << x << "," << y;
      }
      if (reach < 1.5f) {
        near_sum += alpha;
        ++near;
      }
      if (reach > 8) {
        ++far;
        far_exact += value == 1.0f;
      }
    }
  ASSERT_GT(near, 4);
  ASSERT_GT(far, 100);
  EXPECT_GT(near_sum / near, 0.25);         // the shadow round the contact is dark (opacity 0.34 measured)
  EXPECT_GT(double(far_exact) / far, 0.9);  // far from the sphere, almost no sample is shadowed
  EXPECT_EQ(on_map.color.at(kCatcherSize / 2, 0).x, 1.0f);  // the sky above
}

// A coloured sphere floating over a mirror shadow catcher at z = 0, seen from above at an angle.
SceneDesc mirror_catcher_scene(bool catcher) {
  SceneDesc scene;
  scene.objects.push_back({SphereObject{{0, 0, 1.5f}, kRadius}, DiffuseMaterial{{0.8f, 0.4f, 0.2f}}});
  SceneObject ground{PlaneObject{}, MirrorMaterial{}};
  ground.ground = Ground{0.0f, catcher};
  scene.objects.push_back(ground);
  scene.camera.position = {0, -6, 3};
  scene.camera.look_at = {0, 0, 0.5f};
  scene.camera.fov_deg = 50;
  return scene;
}

// Whether the ray from `origin` along `direction` meets the sphere of mirror_catcher_scene.
bool meets_floating_sphere(Vec3 origin, Vec3 direction) {
  const Vec3 oc = origin - Vec3{0, 0, 1.5f};
  const float b = dot(oc, direction);
  return b * b - (dot(oc, oc) - kRadius * kRadius) >= 0 && -b > 0;
}

TEST(RenderPasses, MirrorShadowCatcherCarriesTheReflectionInColourAndAlpha) {
  constexpr int kMirrorSize = 48, kSpp = 64;
  RenderSettings s = settings(kMirrorSize);
  s.passes = {AuxPass::Alpha};
  s.background.mode = BackgroundMode::Transparent;
  const Rendered cut_out = render(mirror_catcher_scene(true), s, kSpp);
  s.background.mode = BackgroundMode::Map;
  const Rendered seen = render(mirror_catcher_scene(false), s, kSpp);  // the mirror visible

  const PerspectiveCamera camera(mirror_catcher_scene(true).camera, kMirrorSize, kMirrorSize);
  int reflecting = 0, plain = 0;
  Rgb caught{}, visible{};
  for (int y = 0; y < kMirrorSize; ++y)
    for (int x = 0; x < kMirrorSize; ++x) {
      int on_mirror = 0, mirrored = 0;  // of the pixel's corners: on the mirror; seeing the sphere in it
      for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}}) {
        const Ray ray = camera.generate(float(x) + dx, float(y) + dy);
        if (ray.direction.z >= 0 || meets_floating_sphere(ray.origin, ray.direction)) continue;
        ++on_mirror;
        const Vec3 p = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
        mirrored += meets_floating_sphere(p, {ray.direction.x, ray.direction.y, -ray.direction.z});
      }
      if (on_mirror < 4) continue;
      const float alpha = cut_out.alpha->at(x, y).x;
      if (mirrored == 4) {  // the sphere's reflection: opaque, its colour
        EXPECT_EQ(alpha, 1.0f) << x << "," << y;
        caught += cut_out.color.at(x, y);
        visible += seen.color.at(x, y);
        ++reflecting;
      } else if (mirrored == 0) {  // the map's reflection: the background exactly, transparent
        EXPECT_EQ(alpha, 0.0f) << x << "," << y;
        EXPECT_EQ(cut_out.color.at(x, y), (Rgb{0, 0, 0})) << x << "," << y;
        ++plain;
      }
    }
  ASSERT_GT(reflecting, 20);
  ASSERT_GT(plain, 200);
  caught = caught / float(reflecting), visible = visible / float(reflecting);
  // The reflection is what the visible mirror shows there (other samples, so within their noise).
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(caught[c], visible[c], 0.03f * visible[c]) << c;
  EXPECT_GT(caught.x, 1.5f * caught.y);  // the sphere's orange, not grey
  EXPECT_GT(caught.y, 1.5f * caught.z);
}

TEST(RenderPasses, GroundWithoutHeightLiesUnderTheBoundsAndIsVisibleWithoutCatcher) {
  SceneDesc scene = catcher_scene();
  scene.objects[1].ground->shadow_catcher = false;
  scene.objects[1].material = DiffuseMaterial{{0.5f, 0.5f, 0.5f}};
  scene.objects[0].shape = SphereObject{{0, 0, 3}, kRadius};  // lowest z 2
  RenderSettings s = settings(16);
  s.passes = {AuxPass::Depth, AuxPass::Alpha};
  const Rendered r = render(scene, s, 4);
  // The bottom row looks down on the ground: covered, at the distance to the plane z = 2.
  const PerspectiveCamera camera(scene.camera, 16, 16);
  const Ray ray = camera.generate(0.5f, 15.5f);
  EXPECT_EQ(r.alpha->at(0, 15).x, 1.0f);
  EXPECT_NEAR(r.depth->at(0, 15).x, (2 - ray.origin.z) / ray.direction.z, 0.2f);
  EXPECT_LT(r.color.at(0, 15).x, 0.9f);  // a 0.5 albedo ground, not the white sky
}

// Sphere on a visible ground under a white map: light bounces between them.
SceneDesc bouncing_scene() {
  SceneDesc scene = catcher_scene();
  scene.objects[1].ground->shadow_catcher = false;
  return scene;
}

double mean_of(const Image& image) {
  double sum = 0;
  for (const float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

TEST(RenderPasses, ClampLowersIndirectLightOnly) {
  RenderSettings s = settings(24);
  const Image free = render(bouncing_scene(), s, 8).color;
  s.clamp = 0.05f;
  const Image clamped = render(bouncing_scene(), s, 8).color;
  EXPECT_GT(mean_of(free) - mean_of(clamped), 0.005);  // the sky, most of the image, stays as it is
  for (size_t i = 0; i < free.data().size(); ++i) ASSERT_LE(clamped.data()[i], free.data()[i] + 1e-6f);

  // One bounce: the light reaching the first hit straight from the map, which the clamp does not touch.
  s = settings(24, 1);
  const Image direct = render(bouncing_scene(), s, 8).color;
  s.clamp = 0.05f;
  const Image direct_clamped = render(bouncing_scene(), s, 8).color;
  for (size_t i = 0; i < direct.data().size(); ++i) ASSERT_EQ(direct_clamped.data()[i], direct.data()[i]);
}

TEST(RenderPasses, FilmHoldsPassPlanesOnlyWhenAsked) {
  const int64_t bare = Film::memory_bytes(10, 10);
  EXPECT_EQ(Film::memory_bytes(10, 10, {}), bare);
  EXPECT_EQ(Film::memory_bytes(10, 10, {AuxPass::Alpha}), bare + 100 * 12);
  const PassSet all{AuxPass::Albedo, AuxPass::Normal, AuxPass::Depth, AuxPass::Alpha};
  EXPECT_EQ(all.channels(), 9);
  EXPECT_EQ(Film::memory_bytes(10, 10, all), bare + 100 * 9 * 12);
  EXPECT_EQ(PartialFilm::memory_bytes(10, 10, all), PartialFilm::memory_bytes(10, 10) + 100 * 9 * 8);
}

TEST(RenderPasses, RangesWithPassesMergeIntoTheImageOfOnePass) {
  RenderSettings s = with_passes({AuxPass::Normal, AuxPass::Depth, AuxPass::Alpha});
  s.width = s.height = 17;
  s.spp = 8;
  Renderer whole(sphere_scene(), lighting(LightingMode::EnvMap), s, test::constant_map(1));
  std::atomic<bool> cancel{false};
  whole.render_pass(8, cancel, {});
  Renderer split(sphere_scene(), lighting(LightingMode::EnvMap), s, test::constant_map(1));
  auto first = split.render_range({0, 3}, cancel);
  auto second = split.render_range({3, 8}, cancel);
  ASSERT_TRUE(first && second);
  // Through the bytes a worker sends.
  RangePartial merged = decode_partial(encode_partial(*first), 1 << 20);
  merged.film.merge(decode_partial(encode_partial(*second), 1 << 20).film);
  for (const AuxPass p : {AuxPass::Normal, AuxPass::Depth, AuxPass::Alpha}) {
    const Image a = merged.film.mean(p), b = whole.image(p);
    for (size_t i = 0; i < a.data().size(); ++i) {
      const float x = a.data()[i], y = b.data()[i];
      if (std::isinf(y))
        ASSERT_EQ(x, y);
      else
        ASSERT_NEAR(x, y, 1e-5f * std::max(1.0f, std::abs(y))) << enum_name(p) << " " << i;
    }
  }
  EXPECT_THROW(merged.film.merge(PartialFilm(17, 17)), Error);  // other passes do not merge
}

}  // namespace
}  // namespace lp::render

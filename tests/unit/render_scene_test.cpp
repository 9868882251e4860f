// The renderer as a component: presets, progressive passes, determinism, cancellation, statistics,
// errors, meshes, and geometric checks of the camera, the map rotation and refraction.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "engine/core/error.hpp"
#include "render_test_helpers.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

using test::constant_map;
using test::lighting;
using test::settings;

// Bright (radiance 1) above the horizon, black below.
std::shared_ptr<const EnvMap> sky_map() {
  return test::make_map(64, [](Vec3 d) { return d.z > 0 ? Rgb{1, 1, 1} : Rgb{0, 0, 0}; });
}

ErrorKind error_kind(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.kind();
  }
  ADD_FAILURE() << "no lp::Error thrown";
  return ErrorKind::InvalidData;
}

TEST(RenderScene, PresetsExistAndRender) {
  for (const char* name : {"sphere", "materials", "furnace"}) {
    const auto scene = scene_preset(name);
    ASSERT_TRUE(scene) << name;
    for (LightingMode mode : {LightingMode::EnvMap, LightingMode::Uniform, LightingMode::Bsdf, LightingMode::MedianCut,
                              LightingMode::MedianCutAll}) {
      const Image image = test::render(*scene, lighting(mode, 16), settings(16), constant_map(1.0f), 2);
      for (float v : image.data()) ASSERT_TRUE(std::isfinite(v) && v >= 0) << name;
    }
  }
  EXPECT_EQ(scene_preset("materials")->objects.size(), 5u);
  EXPECT_FALSE(scene_preset("teapot"));
}

TEST(RenderScene, ProgressivePassesTilesAndStatistics) {
  RenderSettings s = settings(40);
  s.height = 24;
  Renderer renderer(*scene_preset("sphere"), lighting(LightingMode::EnvMap), s, sky_map());
  EXPECT_EQ(renderer.tile_count(), 3 * 2);  // 16-pixel tiles
  EXPECT_EQ(renderer.spp_done(), 0);
  const Image empty = renderer.image();
  EXPECT_EQ(empty.width(), 40);
  EXPECT_EQ(empty.height(), 24);
  for (float v : empty.data()) EXPECT_EQ(v, 0.0f);

  std::atomic<bool> cancel{false};
  std::atomic<int> tiles{0};
  EXPECT_TRUE(renderer.render_pass(3, cancel, [&] { ++tiles; }));
  EXPECT_TRUE(renderer.render_pass(5, cancel, [&] { ++tiles; }));
  EXPECT_EQ(tiles.load(), 2 * renderer.tile_count());
  EXPECT_EQ(renderer.spp_done(), 8);
  const RenderStats st = renderer.stats();
  EXPECT_EQ(st.samples, uint64_t(40 * 24 * 8));
  EXPECT_GT(st.rays, st.samples);  // camera rays, shadow rays and bounces
}

TEST(RenderScene, DeterministicForASeedWhateverThePasses) {
  const auto map = sky_map();
  const SceneDesc scene = *scene_preset("materials");
  std::atomic<bool> cancel{false};
  Renderer one(scene, lighting(LightingMode::EnvMap), settings(24), map);
  one.render_pass(8, cancel, {});
  Renderer two(scene, lighting(LightingMode::EnvMap), settings(24), map);
  two.render_pass(3, cancel, {});
  two.render_pass(5, cancel, {});
  Renderer other_seed(scene, lighting(LightingMode::EnvMap), settings(24, 8, 2), map);
  other_seed.render_pass(8, cancel, {});
  const Image a = one.image(), b = two.image(), c = other_seed.image();
  double max_diff = 0, seed_diff = 0;
  for (size_t i = 0; i < a.data().size(); ++i) {
    max_diff = std::max(max_diff, double(std::abs(a.data()[i] - b.data()[i])) / (1e-3 + a.data()[i]));
    seed_diff += std::abs(a.data()[i] - c.data()[i]);
  }
  EXPECT_LT(max_diff, 1e-5);  // the same samples; only the summation order of passes differs
  EXPECT_GT(seed_diff, 1.0);
}

TEST(RenderScene, CancelledPassIsNotAdded) {
  Renderer renderer(*scene_preset("sphere"), lighting(LightingMode::EnvMap), settings(32), sky_map());
  std::atomic<bool> cancel{false};
  ASSERT_TRUE(renderer.render_pass(2, cancel, {}));
  const Image before = renderer.image();
  cancel = true;
  int tiles = 0;
  EXPECT_FALSE(renderer.render_pass(4, cancel, [&] { ++tiles; }));
  EXPECT_EQ(tiles, 0);
  EXPECT_EQ(renderer.spp_done(), 2);
  const Image after = renderer.image();
  for (size_t i = 0; i < before.data().size(); ++i) ASSERT_EQ(before.data()[i], after.data()[i]);

  // Cancelled halfway: the tiles done so far are discarded too.
  std::atomic<bool> cancel_later{false};
  std::atomic<int> done{0};
  EXPECT_FALSE(renderer.render_pass(4, cancel_later, [&] {
    if (++done == 2) cancel_later = true;
  }));
  EXPECT_EQ(renderer.spp_done(), 2);
  EXPECT_LT(done.load(), renderer.tile_count());
}

TEST(RenderScene, ErrorsHaveKinds) {
  const auto map = constant_map(1.0f);
  const Lighting l = lighting(LightingMode::EnvMap);
  SceneDesc scene = *scene_preset("sphere");

  SceneDesc bad_camera = scene;
  bad_camera.camera.look_at = bad_camera.camera.position;
  EXPECT_EQ(error_kind([&] { Renderer(bad_camera, l, settings(8), map); }), ErrorKind::InvalidArgument);
  bad_camera = scene;
  bad_camera.camera.up = {0, 1, 0};  // parallel to the view direction
  EXPECT_EQ(error_kind([&] { Renderer(bad_camera, l, settings(8), map); }), ErrorKind::InvalidArgument);
  bad_camera = scene;
  bad_camera.camera.fov_deg = 180;
  EXPECT_EQ(error_kind([&] { Renderer(bad_camera, l, settings(8), map); }), ErrorKind::InvalidArgument);

  SceneDesc bad_sphere = scene;
  bad_sphere.objects[0].shape = SphereObject{{0, 0, 0}, 0};
  EXPECT_EQ(error_kind([&] { Renderer(bad_sphere, l, settings(8), map); }), ErrorKind::InvalidArgument);
  SceneDesc bad_plane = scene;
  bad_plane.objects[0].shape = PlaneObject{{0, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(error_kind([&] { Renderer(bad_plane, l, settings(8), map); }), ErrorKind::InvalidArgument);
  SceneDesc bad_material = scene;
  bad_material.objects[0].material = DielectricMaterial{-1};
  EXPECT_EQ(error_kind([&] { Renderer(bad_material, l, settings(8), map); }), ErrorKind::InvalidArgument);

  RenderSettings bad = settings(8);
  bad.width = 0;
  EXPECT_EQ(error_kind([&] { Renderer(scene, l, bad, map); }), ErrorKind::InvalidArgument);
  bad = settings(8, -1);
  EXPECT_EQ(error_kind([&] { Renderer(scene, l, bad, map); }), ErrorKind::InvalidArgument);
  EXPECT_EQ(error_kind([&] { Renderer(scene, l, settings(8), nullptr); }), ErrorKind::InvalidArgument);
  Lighting bad_lights = lighting(LightingMode::MedianCut, 0);
  EXPECT_EQ(error_kind([&] { Renderer(scene, bad_lights, settings(8), map); }), ErrorKind::InvalidArgument);
  Lighting bad_intensity = l;
  bad_intensity.intensity = -1;
  EXPECT_EQ(error_kind([&] { Renderer(scene, bad_intensity, settings(8), map); }), ErrorKind::InvalidArgument);

  Renderer ok(scene, l, settings(8), map);
  std::atomic<bool> cancel{false};
  EXPECT_EQ(error_kind([&] { ok.render_pass(0, cancel, {}); }), ErrorKind::InvalidArgument);
}

TEST(RenderScene, MeshesLoadWithLimitsAndErrors) {
  const auto map = constant_map(1.0f);
  const Lighting l = lighting(LightingMode::EnvMap);
  const auto bunny = lp::test::mesh_path("bunny.obj");
  SceneDesc scene = *scene_preset("sphere");
  // The bunny is y-up, about 10 units tall: scale it down and stand it up on z.
  scene.objects[0].shape = MeshObject{bunny, {0, 0, -0.5f}, 0.15f, {0, 0, 0}, nullptr, false, UpAxis::Y};
  const Image image = test::render(scene, l, settings(32), map, 4);
  int covered = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) covered += image.at(x, y).x < 0.9f;  // darker than the background
  EXPECT_GT(covered, 50);

  RenderSettings limited = settings(8);
  limited.mesh_limits.max_triangles = 1000;  // the bunny has ~3.7k
  EXPECT_EQ(error_kind([&] { Renderer(scene, l, limited, map); }), ErrorKind::TooLarge);
  limited = settings(8);
  limited.mesh_limits.max_file_bytes = 1000;
  EXPECT_EQ(error_kind([&] { Renderer(scene, l, limited, map); }), ErrorKind::TooLarge);

  SceneDesc missing = scene;
  missing.objects[0].shape = MeshObject{lp::test::mesh_path("no_such.obj"), {}, 1, {}, nullptr, false, {}};
  EXPECT_EQ(error_kind([&] { Renderer(missing, l, settings(8), map); }), ErrorKind::NotFound);

  const auto dir = std::filesystem::temp_directory_path() / "lp_render_scene_test";
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(dir / name) << text;
    SceneDesc s = scene;
    s.objects[0].shape = MeshObject{dir / name, {}, 1, {}, nullptr, false, {}};
    return s;
  };
  const SceneDesc no_faces = write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(error_kind([&] { Renderer(no_faces, l, settings(8), map); }), ErrorKind::Corrupt);
  const SceneDesc bad_index = write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  EXPECT_EQ(error_kind([&] { Renderer(bad_index, l, settings(8), map); }), ErrorKind::Corrupt);
  std::filesystem::remove_all(dir);
}

TEST(RenderScene, BlackMapRendersBlackInEveryMode) {
  for (LightingMode mode : {LightingMode::EnvMap, LightingMode::Uniform, LightingMode::Bsdf, LightingMode::MedianCut,
                            LightingMode::MedianCutAll}) {
    const Image image = test::render(*scene_preset("materials"), lighting(mode), settings(16), constant_map(0.0f), 2);
    for (float v : image.data()) ASSERT_EQ(v, 0.0f) << int(mode);
  }
}

TEST(RenderScene, MaxDepthZeroSeesOnlyTheMap) {
  const Image image = test::render(*scene_preset("sphere"), lighting(LightingMode::EnvMap), settings(16, 0), constant_map(1.0f), 2);
  EXPECT_EQ(image.at(8, 8).x, 0.0f);  // the sphere: no bounce allowed, no light
  EXPECT_EQ(image.at(0, 0).x, 1.0f);  // the background
}

TEST(RenderScene, MapRotationTurnsTheLightAboutZ) {
  // The map is bright (4) in a cap of 25 degrees about +x. The camera looks along +y at the sphere's
  // -y side, +x to the right. Unrotated, the right side is lit and the left side dark. Rotated by +90
  // degrees the cap moves to +y (behind the sphere): the facing point is dark; by -90 it moves to -y
  // (the camera side): the facing point is lit. By 180 the left side is lit.
  const auto map = test::make_map(128, [](Vec3 d) { return d.x > 0.9f ? Rgb{4, 4, 4} : Rgb{0, 0, 0}; });
  for (LightingMode mode : {LightingMode::EnvMap, LightingMode::MedianCutAll}) {
    const auto render_rotated = [&](float degrees) {
      Lighting l = lighting(mode, 16);
      l.rotation_deg = degrees;
      l.visible = false;
      return test::render(*scene_preset("sphere"), l, settings(32), map, 16);
    };
    const Image none = render_rotated(0), plus90 = render_rotated(90), minus90 = render_rotated(-90),
                half_turn = render_rotated(180);
    EXPECT_GT(none.at(25, 16).x, 0.3f) << int(mode);
    EXPECT_EQ(none.at(6, 16).x, 0.0f) << int(mode);
    EXPECT_EQ(plus90.at(16, 16).x, 0.0f) << int(mode);
    EXPECT_GT(minus90.at(16, 16).x, 0.3f) << int(mode);
    EXPECT_GT(half_turn.at(6, 16).x, 0.3f) << int(mode);
    EXPECT_EQ(half_turn.at(25, 16).x, 0.0f) << int(mode);
  }
}

TEST(RenderScene, GlassSphereInvertsTheSky) {
  // A ball lens images the distant scene upside down: the top of a glass sphere shows the dark
  // ground, its bottom the bright sky (Fresnel reflections aside).
  SceneDesc scene = *scene_preset("sphere");
  scene.objects[0].material = DielectricMaterial{1.5f};
  Lighting l = lighting(LightingMode::EnvMap);
  const Image image = test::render(scene, l, settings(32, 16), sky_map(), 32);
  EXPECT_LT(image.at(16, 9).x, 0.25f);   // upper part of the sphere
  EXPECT_GT(image.at(16, 22).x, 0.75f);  // lower part
  EXPECT_EQ(image.at(16, 0).x, 1.0f);    // sky above the sphere
}

}  // namespace
}  // namespace lp::render

// Rays/s of the path tracer on a model: a 6 x 6 square seen at an angle on forest.exr, with its material
// untextured (factors only), with a base-colour texture, and with base-colour, metallic-roughness and
// normal textures; mipmaps (ray cones) on and off. The difference is the cost of texturing.
// Run: ./build/bin/textured_render_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <memory>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/renderer.hpp"
#include "support/test_data.hpp"
#include "unit/model_test_scenes.hpp"

namespace lp::render {
namespace {

std::shared_ptr<const EnvMap> forest() {
  static const auto map =
      std::make_shared<const EnvMap>(read_image_file(lp::bench::envmap_path("forest.exr")).image);
  return map;
}

constexpr int kSize = 128, kSpp = 8;

// textures: 0 none, 1 base colour, 2 base colour + metallic-roughness + normal map.
SceneDesc square_scene(int textures) {
  ModelMaterial m = test::rough_dielectric({0.8f, 0.8f, 0.8f});
  m.roughness_factor = 0.5f;
  if (textures >= 1)
    m.base_color = test::bind(test::make_texture(512, 512, [](int x, int y) {
      return ((x / 32 + y / 32) % 2) ? Rgb{0.9f, 0.8f, 0.2f} : Rgb{0.1f, 0.2f, 0.7f};
    }));
  if (textures >= 2) {
    m.metallic_roughness = test::bind(test::make_texture(256, 256, [](int x, int) {
      return Rgb{0, 0.3f + 0.7f * float(x % 64) / 64.0f, float((x / 64) % 2)};
    }));
    m.normal = test::bind(test::make_texture(256, 256, [](int x, int y) {
      const float nx = 0.3f * std::sin(float(x) * 0.2f), ny = 0.3f * std::cos(float(y) * 0.2f);
      return Rgb{0.5f * (nx + 1), 0.5f * (ny + 1), 0.5f * (std::sqrt(1 - nx * nx - ny * ny) + 1)};
    }));
  }
  SceneDesc scene;
  scene.camera.position = {0, -5, 2.5f};
  scene.camera.look_at = {0, 0, 0};
  scene.objects.push_back(test::model_object(test::square_model(3, 1, m)));
  return scene;
}

// args: textures, mipmaps.
void BM_TexturedRender(benchmark::State& state) {
  Lighting lighting;
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = kSpp;
  settings.mipmaps = state.range(1) != 0;
  tbb::task_arena arena(2);
  Renderer renderer(square_scene(int(state.range(0))), lighting, settings, forest());
  std::atomic<bool> cancel{false};
  for (auto _ : state) arena.execute([&] { renderer.render_pass(kSpp, cancel, {}); });
  const RenderStats s = renderer.stats();
  state.counters["rays/s"] = benchmark::Counter(double(s.rays), benchmark::Counter::kIsRate);
  state.counters["rays/sample"] = double(s.rays) / double(s.samples);
}
BENCHMARK(BM_TexturedRender)
    ->ArgNames({"textures", "mipmaps"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Args({2, 1})
    ->Args({2, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace lp::render

BENCHMARK_MAIN();

// The path tracer: the `sphere` and `materials` presets on forest.exr (1024 x 512) at fixed spp and
// thread count, reporting camera samples/s and rays/s (all rays: camera, bounce, shadow); and the raw
// Embree throughput (rtcIntersect1 / rtcOccluded1 on the same scenes, random rays) as the ceiling.
// Rates are per wall-clock second; the *_per_cpu_s counters divide by the process CPU time instead (all
// threads), which stays meaningful when other work shares the cores.
// Run: ./build/bin/render_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <atomic>
#include <ctime>
#include <memory>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "engine/core/rng.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/renderer.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

std::shared_ptr<const EnvMap> forest() {
  static const auto map = std::make_shared<const EnvMap>(read_image_file(test::envmap_path("forest.exr")).image);
  return map;
}

const char* const kPresets[] = {"sphere", "materials"};
constexpr int kSize = 128, kSpp = 8;

// args: preset index, lighting mode, threads.
void BM_Render(benchmark::State& state) {
  const auto preset = *scene_preset(kPresets[state.range(0)]);
  Lighting lighting;
  lighting.mode = LightingMode(state.range(1));
  lighting.lights = 64;
  RenderSettings settings;
  settings.width = settings.height = kSize;
  tbb::task_arena arena(int(state.range(2)));
  Renderer renderer(preset, lighting, settings, forest());
  std::atomic<bool> cancel{false};
  const std::clock_t cpu0 = std::clock();
  for (auto _ : state) arena.execute([&] { renderer.render_pass(kSpp, cancel, {}); });
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const RenderStats s = renderer.stats();
  state.counters["samples/s"] = benchmark::Counter(double(s.samples), benchmark::Counter::kIsRate);
  state.counters["rays/s"] = benchmark::Counter(double(s.rays), benchmark::Counter::kIsRate);
  state.counters["samples_per_cpu_s"] = double(s.samples) / cpu;
  state.counters["rays_per_cpu_s"] = double(s.rays) / cpu;
  state.counters["rays/sample"] = double(s.rays) / double(s.samples);
}
BENCHMARK(BM_Render)
    ->ArgNames({"preset", "mode", "threads"})
    ->Args({0, int(LightingMode::EnvMap), 1})->Args({0, int(LightingMode::EnvMap), 2})
    ->Args({0, int(LightingMode::Uniform), 2})->Args({0, int(LightingMode::Bsdf), 2})
    ->Args({0, int(LightingMode::MedianCut), 2})->Args({0, int(LightingMode::MedianCutAll), 2})
    ->Args({1, int(LightingMode::EnvMap), 1})->Args({1, int(LightingMode::EnvMap), 2})
    ->Args({1, int(LightingMode::Bsdf), 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

// Random rays from inside the scene's bounds to anywhere: the ceiling of what the tracer could reach.
std::vector<Ray> random_rays(size_t n) {
  std::vector<Ray> rays(n);
  Rng rng(1, 2);
  for (Ray& r : rays) {
    r.origin = {rng.uniform_float() * 6 - 3, rng.uniform_float() * 8 - 6, rng.uniform_float() * 3 - 0.4f};
    const float z = 1 - 2 * rng.uniform_float(), phi = 2 * kPiF * rng.uniform_float(), s = std::sqrt(1 - z * z);
    r.direction = {s * std::cos(phi), s * std::sin(phi), z};
  }
  return rays;
}

// args: preset index, 0 = rtcIntersect1 / 1 = rtcOccluded1, threads.
void BM_EmbreeRaw(benchmark::State& state) {
  const EmbreeScene scene(*scene_preset(kPresets[state.range(0)]), {});
  const std::vector<Ray> rays = random_rays(1 << 16);
  const bool occluded = state.range(1) == 1;
  tbb::task_arena arena(int(state.range(2)));
  std::atomic<uint64_t> hits{0};
  const std::clock_t cpu0 = std::clock();
  for (auto _ : state) {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
        RTCIntersectContext context;
        uint64_t local = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
          rtcInitIntersectContext(&context);
          RTCRayHit rh{};
          rh.ray.org_x = rays[i].origin.x, rh.ray.org_y = rays[i].origin.y, rh.ray.org_z = rays[i].origin.z;
          rh.ray.dir_x = rays[i].direction.x, rh.ray.dir_y = rays[i].direction.y, rh.ray.dir_z = rays[i].direction.z;
          rh.ray.tfar = std::numeric_limits<float>::infinity();
          rh.ray.mask = ~0u;
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          if (occluded) {
            rtcOccluded1(scene.handle(), &context, &rh.ray);
            local += rh.ray.tfar < 0;
          } else {
            rtcIntersect1(scene.handle(), &context, &rh);
            local += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
          }
        }
        hits += local;
      });
    });
  }
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  state.counters["rays/s"] = benchmark::Counter(double(state.iterations() * rays.size()), benchmark::Counter::kIsRate);
  state.counters["rays_per_cpu_s"] = double(state.iterations() * rays.size()) / cpu;
  state.counters["hit_fraction"] = double(hits.load()) / double(state.iterations() * rays.size());
}
BENCHMARK(BM_EmbreeRaw)
    ->ArgNames({"preset", "occluded", "threads"})
    ->Args({0, 0, 1})->Args({0, 0, 2})->Args({0, 1, 2})->Args({1, 0, 1})->Args({1, 0, 2})->Args({1, 1, 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lp::render

BENCHMARK_MAIN();

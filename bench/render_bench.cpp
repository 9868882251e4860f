// The path tracer: the `sphere` and `materials` presets, the sphere as rough gold (GGX alpha 0.5), and
// the bunny on a plane (bench/scenes/bunny.json), on forest.exr (1024 x 512) at fixed spp and thread count,
// reporting camera samples/s and rays/s (all rays: camera, bounce, shadow); and the raw Embree throughput
// (rtcIntersect1 / rtcOccluded1 on the same scenes, random rays) as the ceiling, and the tracer's rays/s as a
// fraction of it measured side by side (RenderOfCeiling). Rates are per wall-clock second; the *_per_cpu_s
// counters divide by the process CPU time instead (all threads), which stays meaningful when other work
// shares the cores.
// Run: ./build/bin/render_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <ctime>
#include <memory>
#include <vector>

#include "bench_data.hpp"
#include "bench_scene_file.hpp"
#include "engine/core/rng.hpp"
#include "engine/fresnel/metals.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/renderer.hpp"

namespace lp::render {
namespace {

std::shared_ptr<const EnvMap> forest() {
  static const auto map =
      std::make_shared<const EnvMap>(read_image_file(bench::envmap_path("forest.exr")).image);
  return map;
}

const char* const kPresets[] = {"sphere", "materials"};
constexpr int kSize = 128, kSpp = 8;
constexpr int kRoughGold = 2, kBunny = 3;  // the scene indices after the presets

SceneDesc bench_scene(int index) {
  if (index == kBunny) return bench::bench_scene_file("bunny.json");
  if (index != kRoughGold) return *scene_preset(kPresets[index]);
  SceneDesc s = *scene_preset("sphere");
  const ConductorPreset& gold = lookup_metal("gold");
  s.objects[0].material = ConductorMaterial{gold.eta_rgb(), gold.k_rgb(), 0.5f};
  return s;
}

// args: scene index, lighting mode, threads.
void BM_Render(benchmark::State& state) {
  const SceneDesc preset = bench_scene(int(state.range(0)));
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
    ->ArgNames({"scene", "mode", "threads"})
    ->Args({0, int(LightingMode::EnvMap), 1})
    ->Args({0, int(LightingMode::EnvMap), 2})
    ->Args({0, int(LightingMode::Uniform), 2})
    ->Args({0, int(LightingMode::Bsdf), 2})
    ->Args({0, int(LightingMode::MedianCut), 2})
    ->Args({0, int(LightingMode::MedianCutAll), 2})
    ->Args({1, int(LightingMode::EnvMap), 1})
    ->Args({1, int(LightingMode::EnvMap), 2})
    ->Args({1, int(LightingMode::Bsdf), 2})
    ->Args({kRoughGold, int(LightingMode::EnvMap), 2})
    ->Args({kRoughGold, int(LightingMode::Bsdf), 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// An 8192 x 4096 map (forest.exr enlarged) lighting the sphere preset, sampled on an importance grid
// `grid_width` wide (2048: the default, level 2 of the map; 8192: the map's own grid): rays/s, and
// what the map holds with its grid.
std::shared_ptr<const EnvMap> large_map() {
  return std::make_shared<const EnvMap>(resize_box(forest()->image(), 8192, 4096));
}

// args: grid width, threads.
void BM_RenderLargeMap(benchmark::State& state) {
  static const auto map = large_map();
  Lighting lighting;
  lighting.importance_max_width = int(state.range(0));
  RenderSettings settings;
  settings.width = settings.height = kSize;
  tbb::task_arena arena(int(state.range(1)));
  Renderer renderer(*scene_preset("sphere"), lighting, settings, map);
  std::atomic<bool> cancel{false};
  for (auto _ : state) arena.execute([&] { renderer.render_pass(kSpp, cancel, {}); });
  const RenderStats s = renderer.stats();
  state.counters["rays/s"] = benchmark::Counter(double(s.rays), benchmark::Counter::kIsRate);
  state.counters["map_MB"] = double(map->memory_bytes()) / 1e6;
}
BENCHMARK(BM_RenderLargeMap)
    ->ArgNames({"grid_width", "threads"})
    ->Args({2048, 2})
    ->Args({8192, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The first render of a map builds its importance grid: the renderer's setup on a fresh 8K map.
// args: grid width.
void BM_RenderSetupLargeMap(benchmark::State& state) {
  Lighting lighting;
  lighting.importance_max_width = int(state.range(0));
  RenderSettings settings;
  settings.width = settings.height = kSize;
  for (auto _ : state) {
    state.PauseTiming();
    auto map = large_map();
    state.ResumeTiming();
    Renderer renderer(*scene_preset("sphere"), lighting, settings, map);
    benchmark::DoNotOptimize(renderer.tile_count());
  }
}
BENCHMARK(BM_RenderSetupLargeMap)
    ->ArgName("grid_width")
    ->Arg(2048)
    ->Arg(8192)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Random rays from inside the scene's bounds to anywhere: the ceiling of what the tracer could reach.
std::vector<Ray> random_rays(size_t n) {
  std::vector<Ray> rays(n);
  Rng rng(1, 2);
  for (Ray& r : rays) {
    r.origin = {rng.uniform_float() * 6 - 3, rng.uniform_float() * 8 - 6, rng.uniform_float() * 3 - 0.4f};
    const float z = 1 - 2 * rng.uniform_float(), phi = 2 * kPiF * rng.uniform_float(),
                s = std::sqrt(1 - z * z);
    r.direction = {s * std::cos(phi), s * std::sin(phi), z};
  }
  return rays;
}

// Traces `rays` one by one (rtcIntersect1, or rtcOccluded1) on the arena's threads; returns the hits.
uint64_t trace_raw(const EmbreeScene& scene, const std::vector<Ray>& rays, bool occluded,
                   tbb::task_arena& arena) {
  std::atomic<uint64_t> hits{0};
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
          RTCIntersectContext context;
          uint64_t local = 0;
          for (size_t i = r.begin(); i != r.end(); ++i) {
            rtcInitIntersectContext(&context);
            RTCRayHit rh{};
            rh.ray.org_x = rays[i].origin.x, rh.ray.org_y = rays[i].origin.y, rh.ray.org_z = rays[i].origin.z;
            rh.ray.dir_x = rays[i].direction.x, rh.ray.dir_y = rays[i].direction.y,
            rh.ray.dir_z = rays[i].direction.z;
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
  return hits.load();
}

// args: scene index, 0 = rtcIntersect1 / 1 = rtcOccluded1, threads.
void BM_EmbreeRaw(benchmark::State& state) {
  const EmbreeScene scene(bench_scene(int(state.range(0))), {});
  const std::vector<Ray> rays = random_rays(1 << 16);
  const bool occluded = state.range(1) == 1;
  tbb::task_arena arena(int(state.range(2)));
  uint64_t hits = 0;
  const std::clock_t cpu0 = std::clock();
  for (auto _ : state) hits += trace_raw(scene, rays, occluded, arena);
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  state.counters["rays/s"] =
      benchmark::Counter(double(state.iterations() * rays.size()), benchmark::Counter::kIsRate);
  state.counters["rays_per_cpu_s"] = double(state.iterations() * rays.size()) / cpu;
  state.counters["hit_fraction"] = double(hits) / double(state.iterations() * rays.size());
}
BENCHMARK(BM_EmbreeRaw)
    ->ArgNames({"scene", "occluded", "threads"})
    ->Args({0, 0, 1})
    ->Args({0, 0, 2})
    ->Args({0, 1, 2})
    ->Args({1, 0, 1})
    ->Args({1, 0, 2})
    ->Args({1, 1, 2})
    ->Args({kBunny, 0, 1})
    ->Args({kBunny, 0, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The path tracer's rays/s as a fraction of the raw ceiling, both measured in each iteration on the
// same scene, map-lit (envmap mode), at the same thread count: a render pass of kSpp, then as many
// random rays through rtcIntersect1 as the pass traced. of_ceiling compares rates per CPU second (the
// steadier figure when other work shares the cores), of_ceiling_wall per wall second.
// args: scene index, threads.
void BM_RenderOfCeiling(benchmark::State& state) {
  const SceneDesc desc = bench_scene(int(state.range(0)));
  RenderSettings settings;
  settings.width = settings.height = kSize;
  tbb::task_arena arena(int(state.range(1)));
  Renderer renderer(desc, Lighting{}, settings, forest());
  const EmbreeScene scene(desc, {});
  std::atomic<bool> cancel{false};
  double render_cpu = 0, render_wall = 0, raw_cpu = 0, raw_wall = 0;
  uint64_t raw_rays = 0;
  const auto timed = [](double& cpu, double& wall, auto&& work) {
    const std::clock_t c0 = std::clock();
    const auto w0 = std::chrono::steady_clock::now();
    work();
    cpu += double(std::clock() - c0) / CLOCKS_PER_SEC;
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  };
  for (auto _ : state) {
    const uint64_t before = renderer.stats().rays;
    timed(render_cpu, render_wall, [&] { arena.execute([&] { renderer.render_pass(kSpp, cancel, {}); }); });
    const std::vector<Ray> rays = random_rays(size_t(renderer.stats().rays - before));
    timed(raw_cpu, raw_wall, [&] { trace_raw(scene, rays, false, arena); });
    raw_rays += rays.size();
  }
  const double rays = double(renderer.stats().rays);
  state.counters["rays_per_cpu_s"] = rays / render_cpu;
  state.counters["raw_rays_per_cpu_s"] = double(raw_rays) / raw_cpu;
  state.counters["of_ceiling"] = (rays / render_cpu) / (double(raw_rays) / raw_cpu);
  state.counters["of_ceiling_wall"] = (rays / render_wall) / (double(raw_rays) / raw_wall);
}
BENCHMARK(BM_RenderOfCeiling)
    ->ArgNames({"scene", "threads"})
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Args({kBunny, 1})
    ->Args({kBunny, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace lp::render

BENCHMARK_MAIN();

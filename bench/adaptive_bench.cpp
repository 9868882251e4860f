// Adaptive sampling's cost: camera samples per CPU second of adaptive passes (Renderer::
// render_adaptive_pass) beside uniform ones on the same scene, and the allocation of a pass alone.
// In the white furnace lit through BSDF samples, with a 10 degree field that the sphere fills, every
// sample is 0.5 and no pixel has a deviation, so an adaptive pass gives each pixel the same count and
// traces the same paths as a uniform one: the difference is the bookkeeping (the allocation, per-pixel
// counts and runs). On `materials` under forest.exr the samples also move to the costlier pixels (mirror and
// glass rims), so the rate there is the cost of a sample where adaptive sampling puts it.
// BM_DeliveredSpp renders `materials` through render_passes under a small bright sun (fireflies, whose
// neighbourhoods reach the allocation's cap) or forest.exr and counts the samples it traced.
// Run: ./build/bin/adaptive_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <memory>
#include <vector>

#include "bench_data.hpp"
#include "engine/core/rng.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/adaptive_allocation.hpp"
#include "engine/render/pass_schedule.hpp"
#include "engine/render/renderer.hpp"
#include "support/sunny_map.hpp"

namespace lp::render {
namespace {

constexpr int kSize = 128, kSpp = 16;

std::shared_ptr<const EnvMap> map_of(bool furnace) {
  if (!furnace)
    return std::make_shared<const EnvMap>(read_image_file(bench::envmap_path("forest.exr")).image);
  Image white(64, 32);
  for (int y = 0; y < white.height(); ++y)
    for (int x = 0; x < white.width(); ++x) white.set(x, y, {1, 1, 1});
  return std::make_shared<const EnvMap>(std::move(white));
}

// args: scene (0: the sphere of the furnace filling the view, bsdf lighting; 1: materials, envmap lighting on
// forest.exr), adaptive, threads.
void BM_AdaptivePass(benchmark::State& state) {
  const bool furnace = state.range(0) == 0;
  Lighting lighting;
  lighting.mode = furnace ? LightingMode::Bsdf : LightingMode::EnvMap;
  RenderSettings settings;
  settings.width = settings.height = kSize;
  tbb::task_arena arena(int(state.range(2)));
  SceneDesc scene = *scene_preset(furnace ? "furnace" : "materials");
  if (furnace) scene.camera.fov_deg = 10;
  Renderer renderer(scene, lighting, settings, map_of(furnace));
  std::atomic<bool> cancel{false};
  arena.execute([&] { renderer.render_pass(kSpp, cancel, {}); });  // the warm-up, untimed
  const uint64_t samples0 = renderer.stats().samples;
  const std::clock_t cpu0 = std::clock();
  for (auto _ : state)
    arena.execute([&] {
      if (state.range(1))
        renderer.render_adaptive_pass(kSpp, cancel, {});
      else
        renderer.render_pass(kSpp, cancel, {});
    });
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const double samples = double(renderer.stats().samples - samples0);
  state.counters["samples/s"] = benchmark::Counter(samples, benchmark::Counter::kIsRate);
  state.counters["samples_per_cpu_s"] = samples / cpu;
}
BENCHMARK(BM_AdaptivePass)
    ->ArgNames({"scene", "adaptive", "threads"})
    ->Args({0, 0, 1})
    ->Args({0, 1, 1})
    ->Args({1, 0, 1})
    ->Args({1, 1, 1})
    ->Args({1, 0, 2})
    ->Args({1, 1, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// An adaptive render of `materials` at args(0) spp, args(2) x args(2) pixels, under args(1) 0:
// test::firefly_sky, 1: forest.exr: the samples it traced per pixel (mean_spp), spp_done(), and the
// lowest and highest ratio of a pass's samples to its budget.
void BM_DeliveredSpp(benchmark::State& state) {
  RenderSettings settings;
  settings.width = settings.height = int(state.range(2));
  settings.spp = int(state.range(0));
  settings.sampling = SamplingMode::Adaptive;
  Lighting lighting;
  lighting.mode = LightingMode::EnvMap;
  const auto map = state.range(1) == 0 ? std::make_shared<const EnvMap>(test::firefly_sky()) : map_of(false);
  const double pixels = double(settings.width) * settings.height;
  for (auto _ : state) {
    Renderer renderer(*scene_preset("materials"), lighting, settings, map);
    std::atomic<bool> cancel{false};
    double lowest = 2, highest = 0;
    for (const RenderPass& pass : render_passes(settings)) {
      const uint64_t before = renderer.stats().samples;
      renderer.render(pass, cancel, {});
      const double ratio = double(renderer.stats().samples - before) / (pixels * pass.spp);
      lowest = std::min(lowest, ratio), highest = std::max(highest, ratio);
    }
    state.counters["mean_spp"] = double(renderer.stats().samples) / pixels;
    state.counters["spp_done"] = renderer.spp_done();
    state.counters["pass_lowest"] = lowest;
    state.counters["pass_highest"] = highest;
  }
}
BENCHMARK(BM_DeliveredSpp)
    ->ArgNames({"spp", "map", "size"})
    ->ArgsProduct({{16, 64, 1024}, {0, 1}, {64, 256}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The allocation of one pass over kSize x kSize random deviations: time per pixel. args(0) 0: uniform in
// [0, 1); 1: heavy-tailed, 1 / u for uniform u (fireflies: 2% of the pixels are above 50, and some of
// their neighbourhoods reach the cap).
void BM_AllocateSamples(benchmark::State& state) {
  std::vector<float> sigma(size_t(kSize) * kSize);
  Rng rng(1, 0);
  for (float& s : sigma) {
    const float u = rng.uniform_float();
    s = state.range(0) == 0 ? u : 1 / std::max(u, 1e-6f);
  }
  uint32_t pass = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        allocate_samples(sigma, kSize, kSize, uint64_t(kSpp) * kSize * kSize, 1, pass++));
  state.SetItemsProcessed(int64_t(state.iterations()) * kSize * kSize);
}
BENCHMARK(BM_AllocateSamples)->ArgName("tail")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace lp::render

BENCHMARK_MAIN();

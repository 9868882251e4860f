// What an 8192 x 4096 map holds once it has been used: the image, then each table built from it (the
// sampling distribution, the alias table of independent samples, the median-cut summed-area table, the
// variance split's moment tables, the sun's residual map, the renderer's default 2048-wide importance
// grid, the SH projection), one per benchmark on a fresh map with what it needs built first; and all of
// them on one map. Counters in MB: `reserved` (EnvMap::memory_bytes() grows by it, the bytes the budget
// counts), `rss` (resident memory it adds and keeps), `peak` (resident memory at its highest while it
// is built, over what was there before). The map is forest.exr enlarged as bench_data does; the sun
// case adds a 0.5 degree sun to it. Run: build/bin/map_memory_bench.
#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "engine/core/constants.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/envmap/sample_set.hpp"
#include "engine/mediancut/median_cut.hpp"
#include "engine/render/env_light.hpp"
#include "engine/sh/sh_projection.hpp"
#include "engine/sun/sun_extraction.hpp"
#include "process_memory.hpp"

namespace lp {
namespace {

constexpr int kWidth = 8192, kHeight = 4096;
constexpr double kMB = 1e6;

using bench::reset_peak;
using bench::status_bytes;

// The map with its image's bytes reserved, as the server holds it.
std::shared_ptr<EnvMap> fresh_map(bool with_sun = false) {
  Image image = bench::forest(kWidth);
  if (with_sun) {
    const Vec3 axis = normalize(Vec3{0.3f, 0.5f, 0.6f});
    const float cos_radius = std::cos(0.25f * kPiF / 180.0f);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (dot(latlong::direction({(float(x) + 0.5f) / kWidth, (float(y) + 0.5f) / kHeight}), axis) >
            cos_radius)
          image.set(x, y, {2e5f, 1.9e5f, 1.7e5f});
  }
  auto map = std::make_shared<EnvMap>(std::move(image));
  const MemoryBudget budget;
  map->account_memory(budget, budget.reserve(EnvMap::image_bytes(kWidth, kHeight), MemoryUse::Held, "map"));
  return map;
}

void draw_independent(const EnvMapSampler& sampler) {
  std::vector<EnvSample> out(1);
  generate_samples(sampler, {SampleStrategy::Independent, 1, 1}, 0, out);
}

void importance_grid(const std::shared_ptr<const EnvMap>& map) {
  const render::EnvLight light(map, render::Lighting{});  // the default grid: 2048 wide
  benchmark::DoNotOptimize(light.grid_level());
}

struct Component {
  const char* name;
  std::function<void(const std::shared_ptr<EnvMap>&)> before, build;
  bool with_sun = false;
};

const std::vector<Component>& components() {
  static const std::vector<Component> list = {
      {"image", nullptr, nullptr},
      {"distribution", nullptr, [](const auto& m) { m->sampler(LuminanceMode::Average); }},
      {"alias_table", [](const auto& m) { m->sampler(LuminanceMode::Average); },
       [](const auto& m) { draw_independent(*m->sampler(LuminanceMode::Average)); }},
      {"weight_sat", nullptr,
       [](const auto& m) { split_tables(*m, LuminanceMode::Average, SplitRule::Median); }},
      {"moment_sats", [](const auto& m) { split_tables(*m, LuminanceMode::Average, SplitRule::Median); },
       [](const auto& m) { split_tables(*m, LuminanceMode::Average, SplitRule::Variance); }},
      {"sun_residual", [](const auto& m) { split_tables(*m, LuminanceMode::Average, SplitRule::Median); },
       [](const auto& m) { extract_sun(*m, SunParams{}); }, true},
      {"importance_grid_2048", nullptr, [](const auto& m) { importance_grid(m); }},
      {"sh", nullptr, [](const auto& m) { sh_projection_cached(*m); }},
  };
  return list;
}

void report(benchmark::State& state, int64_t reserved, int64_t rss, int64_t peak) {
  state.counters["reserved_MB"] = double(reserved) / kMB;
  state.counters["rss_MB"] = double(rss) / kMB;
  state.counters["peak_MB"] = double(peak) / kMB;
}

// arg: the component's index in components().
void BM_MapComponent(benchmark::State& state) {
  const Component& c = components()[size_t(state.range(0))];
  state.SetLabel(c.name);
  bench::forest(kWidth);  // the enlarged source, made once outside the measurement
  for (auto _ : state) {
    if (!c.build) {  // the map itself
      reset_peak();
      const int64_t before = status_bytes("VmRSS");
      const auto map = fresh_map();
      report(state, map->memory_bytes(), status_bytes("VmRSS") - before, status_bytes("VmHWM") - before);
      continue;
    }
    const auto map = fresh_map(c.with_sun);
    if (c.before) c.before(map);
    reset_peak();
    const int64_t rss = status_bytes("VmRSS"), reserved = map->memory_bytes();
    c.build(map);
    report(state, map->memory_bytes() - reserved, status_bytes("VmRSS") - rss, status_bytes("VmHWM") - rss);
  }
}
BENCHMARK(BM_MapComponent)->DenseRange(0, 7)->Iterations(1)->Unit(benchmark::kMillisecond);

// Everything above on one map (the sun case's map): its memory_bytes() and the resident memory it adds.
void BM_MapTotal(benchmark::State& state) {
  bench::forest(kWidth);
  for (auto _ : state) {
    reset_peak();
    const int64_t before = status_bytes("VmRSS");
    const auto map = fresh_map(true);
    for (const Component& c : components())
      if (c.build) c.build(map);
    state.counters["reserved_MB"] = double(map->memory_bytes()) / kMB;
    state.counters["rss_MB"] = double(status_bytes("VmRSS") - before) / kMB;
    state.counters["peak_MB"] = double(status_bytes("VmHWM") - before) / kMB;
  }
}
BENCHMARK(BM_MapTotal)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

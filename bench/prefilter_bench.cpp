// The prefiltered specular chain (engine/prefilter): the whole chain (level 0 resampled, the map reduced
// for the lobes, levels 1.. convolved) on the real 1024 x 512 forest map and on it enlarged to
// 8192 x 4096, for 256 to 4096 samples per texel; and its parts on the large map.
// Aim (issue 12): base 256 with 1024 samples on an 8192 x 4096 map in seconds.
// Run: ./build/bin/prefilter_bench --benchmark_min_time=1
// "Time" is wall time; "CPU" is the CPU time of all the process's threads.
#include <benchmark/benchmark.h>

#include "bench_data.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/latlong_resample.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/prefilter/prefilter_source.hpp"

namespace lp {
namespace {

const EnvMap& forest(int width) {
  static const EnvMap small(bench::forest(1024));
  if (width == small.width()) return small;
  static const EnvMap large(bench::forest(8192));
  return large;
}

PrefilterParams params(int samples) {
  PrefilterParams p;
  p.samples = samples;
  return p;
}

// args: map width, samples per texel (base 256, 6 levels).
void BM_PrefilterChain(benchmark::State& state) {
  const EnvMap& map = forest(int(state.range(0)));
  const PrefilterParams p = params(int(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(prefilter_chain(map, p)->levels.data());
  state.counters["source_width"] = double(PrefilterSource::width_for(map.width(), p));
  state.SetItemsProcessed(state.iterations() * prefilter_work_units(p));
}
BENCHMARK(BM_PrefilterChain)
    ->Args({1024, 1024})
    ->Args({8192, 256})
    ->Args({8192, 1024})
    ->Args({8192, 4096})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Level 0 of the default chain: 8192 x 4096 to 256 x 128.
void BM_ResampleLevel0(benchmark::State& state) {
  const EnvMap& map = forest(8192);
  for (auto _ : state) benchmark::DoNotOptimize(resample_latlong(map.image(), 256, 128).data().data());
}
BENCHMARK(BM_ResampleLevel0)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

// The map the default chain's lobes read: reduced to its width, with its levels.
void BM_PrefilterSource(benchmark::State& state) {
  const EnvMap& map = forest(8192);
  const int width = PrefilterSource::width_for(map.width(), params(1024));
  for (auto _ : state) benchmark::DoNotOptimize(PrefilterSource(map, width).width());
  state.counters["width"] = width;
}
BENCHMARK(BM_PrefilterSource)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

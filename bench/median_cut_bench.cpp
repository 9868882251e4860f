// Median cut: summed-area table build, and the whole cut (subdivision + light placement) with and
// without the table build, on a real 1024 x 512 map and on the same map enlarged to 8192 x 4096.
// Aims (issue 3): 1024 x 512 with 256 lights <= 5 ms; 8192 x 4096 with 4096 lights <= 300 ms
// including the table. Run: ./build/bin/median_cut_bench --benchmark_min_time=1
// "Time" is wall time; "CPU" is the CPU time of all the process's threads (on a loaded machine, wall
// time depends on what else runs; on an idle one with N cores it lies between CPU / N and CPU).
#include <benchmark/benchmark.h>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/mediancut/median_cut.hpp"

namespace lp {
namespace {

using bench::forest;

MedianCutParams params(int count, SplitRule split = SplitRule::Median) {
  MedianCutParams p;
  p.count = count;
  p.split = split;
  return p;
}

void BM_SatBuild(benchmark::State& state) {
  const Image& image = forest(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(build_weight_table(image, LuminanceMode::Average).total());
  state.SetItemsProcessed(state.iterations() * image.pixel_count());
}
BENCHMARK(BM_SatBuild)
    ->Arg(1024)
    ->Arg(8192)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// The tables already built (as when they are cached on the map): subdivision and light placement.
void BM_MedianCut(benchmark::State& state) {
  const Image& image = forest(int(state.range(0)));
  const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Median);
  for (auto _ : state)
    benchmark::DoNotOptimize(median_cut(image, params(int(state.range(1))), tables).lights.data());
}
BENCHMARK(BM_MedianCut)
    ->Args({1024, 256})
    ->Args({1024, 4096})
    ->Args({8192, 256})
    ->Args({8192, 4096})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Everything from the image: the table build, subdivision and light placement.
void BM_MedianCutWithSat(benchmark::State& state) {
  const Image& image = forest(int(state.range(0)));
  for (auto _ : state) {
    const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Median);
    benchmark::DoNotOptimize(median_cut(image, params(int(state.range(1))), tables).lights.data());
  }
}
BENCHMARK(BM_MedianCutWithSat)
    ->Args({1024, 256})
    ->Args({1024, 4096})
    ->Args({8192, 256})
    ->Args({8192, 4096})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// The variance split, tables included (five tables instead of one).
void BM_MedianCutVarianceWithSat(benchmark::State& state) {
  const Image& image = forest(int(state.range(0)));
  for (auto _ : state) {
    const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Variance);
    benchmark::DoNotOptimize(
        median_cut(image, params(int(state.range(1)), SplitRule::Variance), tables).lights.data());
  }
}
BENCHMARK(BM_MedianCutVarianceWithSat)
    ->Args({1024, 256})
    ->Args({8192, 4096})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

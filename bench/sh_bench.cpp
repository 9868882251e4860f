// Spherical harmonics of a map (all five bands: every coefficient a request can ask for) and the
// split-sum DFG table. Aim (issue 12): the SH of an 8192 x 4096 map in under 100 ms.
// Run: ./build/bin/sh_bench --benchmark_min_time=1
// "Time" is wall time; "CPU" is the CPU time of all the process's threads.
#include <benchmark/benchmark.h>

#include "bench_data.hpp"
#include "engine/ibl/dfg_lut.hpp"
#include "engine/image/image_io.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp {
namespace {

using bench::forest;

void BM_ShProjection(benchmark::State& state) {
  const Image& image = forest(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(project_sh(image).rgb[0][0]);
  state.SetItemsProcessed(state.iterations() * image.pixel_count());
}
BENCHMARK(BM_ShProjection)
    ->Arg(1024)
    ->Arg(8192)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_DfgLut(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(make_dfg_lut(int(state.range(0)), false).texels[0].x);
}
BENCHMARK(BM_DfgLut)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

// Projections of an 8192 x 4096 map (the real 1024 x 512 forest map enlarged): lat-long to a cube of
// faces 1024 and to an equal-area square of side 2048, and back to lat-long at the width an upload of
// them becomes (4096 x 2048) and at the original's (8192 x 4096). Run:
//   ./build/bin/projection_bench --benchmark_min_time=1
// "Time" is wall time; "CPU" is the CPU time of all the process's threads (on a loaded machine, wall
// time depends on what else runs; on an idle one with N cores it lies between CPU / N and CPU).
#include <benchmark/benchmark.h>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/projection/reproject.hpp"

namespace lp {
namespace {

const Image& latlong() {
  static const Image large = resize_box(read_image_file(bench::envmap_path("forest.exr")).image, 8192, 4096);
  return large;
}

// The map in `projection` at `size`, made once.
const Image& projected(Projection projection, int size) {
  static const Image cube = reproject(latlong(), Projection::LatLong, Projection::Cube, 1024);
  static const Image equal_area = reproject(latlong(), Projection::LatLong, Projection::EqualArea, 2048);
  return projection == Projection::Cube && size == 1024 ? cube : equal_area;
}

void report(benchmark::State& state, const Image& out) {
  state.SetItemsProcessed(state.iterations() * out.pixel_count());
  state.counters["output_pixels"] = double(out.pixel_count());
}

void BM_FromLatLong(benchmark::State& state, Projection to, int size) {
  Image out;
  for (auto _ : state) out = reproject(latlong(), Projection::LatLong, to, size);
  report(state, out);
}

void BM_ToLatLong(benchmark::State& state, Projection from, int size) {
  const Image& in = projected(from, size);
  Image out;
  for (auto _ : state) out = reproject(in, from, Projection::LatLong, int(state.range(0)));
  report(state, out);
}

BENCHMARK_CAPTURE(BM_FromLatLong, cube_1024, Projection::Cube, 1024)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FromLatLong, equal_area_2048, Projection::EqualArea, 2048)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ToLatLong, cube_1024, Projection::Cube, 1024)
    ->Arg(4096)
    ->Arg(8192)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ToLatLong, equal_area_2048, Projection::EqualArea, 2048)
    ->Arg(4096)
    ->Arg(8192)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

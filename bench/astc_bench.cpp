// ASTC HDR 4x4 compression of a prefiltered cube chain (six 256 x 256 faces, 6 levels down to 8 x 8, of
// the forest map), written as a KTX 2.0 file, at astcenc's fast (10), medium (60) and thorough (98)
// presets, with 2 threads; and the medium preset's one level 0 face alone.
// Run: ./build/bin/astc_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include "bench_data.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/projection/cube_layout.hpp"

namespace lp {
namespace {

// The chain's levels as the KTX 2.0 writer takes a cube: faces stacked, N x 6N.
const std::vector<Image>& cube_levels() {
  static const std::vector<Image> levels = [] {
    PrefilterParams p;
    p.projection = Projection::Cube;
    p.samples = 64;  // the content's noise does not matter here
    const auto chain = prefilter_chain(EnvMap(bench::forest(1024)), p);
    std::vector<Image> out;
    for (const Image& strip : chain->levels) {
      const int n = strip.height();
      Image stacked(n, 6 * n);
      for (int f = 0; f < 6; ++f) {
        const Image face = cube_strip_face(strip, f);
        for (int y = 0; y < n; ++y) std::copy_n(face.row(y), 3 * n, stacked.row(f * n + y));
      }
      out.push_back(std::move(stacked));
    }
    return out;
  }();
  return levels;
}

void BM_AstcCubeChain(benchmark::State& state) {
  const auto& levels = cube_levels();
  const AstcOptions options{float(state.range(0)), 2};
  size_t bytes = 0;
  for (auto _ : state) bytes = write_ktx2_astc_cube(levels, options).size();
  state.counters["file_bytes"] = double(bytes);
  int64_t texels = 0;
  for (const Image& level : levels) texels += level.pixel_count();
  state.SetItemsProcessed(state.iterations() * texels);
}
BENCHMARK(BM_AstcCubeChain)->Arg(10)->Arg(60)->Arg(98)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AstcFace256(benchmark::State& state) {
  const Image face = ktx2_cube_face(cube_levels()[0], 0);
  AstcHdrEncoder encoder({60.0f, 2});
  for (auto _ : state) benchmark::DoNotOptimize(encoder.compress(face).data());
  state.SetItemsProcessed(state.iterations() * face.pixel_count());
}
BENCHMARK(BM_AstcFace256)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

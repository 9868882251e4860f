// Tone mapping a 4k picture (3840 x 2160, the forest map enlarged and brightened 4x so highlights
// compress) to 8-bit RGB with each curve, as every PNG answer does; and, for scale, the sRGB encoding
// computed with pow per channel (the encoding's cost before it became a table search). Run:
//   ./build/bin/tonemap_bench --benchmark_min_time=1
// "Time" is wall time (all cores, as the server runs it); "CPU" that of all the process's threads.
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/tonemap.hpp"

namespace lp {
namespace {

const Image& picture() {
  static const Image image = [] {
    Image large = resize_box(read_image_file(bench::envmap_path("forest.exr")).image, 3840, 2160);
    for (float& v : large.data()) v *= 4.0f;
    return large;
  }();
  return image;
}

void BM_ToneMapRgb8(benchmark::State& state, ToneCurve curve) {
  const ToneMap tone{.exposure = 0.0f, .gamma = std::nullopt, .curve = curve};
  const Image& image = picture();  // made before the clock starts
  for (auto _ : state) benchmark::DoNotOptimize(tone_map_rgb8(image, tone));
  state.SetItemsProcessed(state.iterations() * picture().pixel_count());
}

// The sRGB curve by pow on each channel, clipped at 1, as 8-bit output was computed before.
void BM_PowPerChannelBaseline(benchmark::State& state) {
  const auto src = picture().data();
  for (auto _ : state) {
    std::vector<uint8_t> out(src.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, src.size(), 1 << 16), [&](const auto& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        const float x = std::clamp(src[i], 0.0f, 1.0f);
        const float e = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
        out[i] = uint8_t(std::lround(e * 255.0f));
      }
    });
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations() * picture().pixel_count());
}

#define LP_TONE_BENCH(name, curve)               \
  BENCHMARK_CAPTURE(BM_ToneMapRgb8, name, curve) \
      ->Unit(benchmark::kMillisecond)            \
      ->MeasureProcessCPUTime()                  \
      ->UseRealTime();

LP_TONE_BENCH(standard, ToneCurve::Standard)
LP_TONE_BENCH(neutral, ToneCurve::Neutral)
LP_TONE_BENCH(agx, ToneCurve::Agx)
LP_TONE_BENCH(aces, ToneCurve::Aces)
LP_TONE_BENCH(reinhard, ToneCurve::Reinhard)
BENCHMARK(BM_PowPerChannelBaseline)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

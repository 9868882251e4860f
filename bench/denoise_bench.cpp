// The denoiser (OIDN's rt_hdr_alb_nrm U-Net on oneDNN) on noisy images of 512x512, 1024x1024 and 1920x1080,
// 1 and 2 threads: time per image, and the peak resident memory beyond the inputs and output (`peak_MB`,
// VmHWM over the resident memory before the run) beside what Denoiser::working_bytes admits for
// (`admitted_MB`), and the CPU seconds of the whole process per image (`process_cpu_s`, all threads: on a
// machine shared with other work, wall time / threads can exceed it by far). A 4096x4096 image (`Large`)
// shows the bound tiling keeps.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <random>

#include "bench/process_memory.hpp"
#include "engine/denoise/denoiser.hpp"

namespace lp::denoise {
namespace {

Image filled(int width, int height, Rgb c) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) img.set(x, y, c);
  return img;
}

Image noisy_gradient(int width, int height) {
  std::mt19937 rng(1);
  std::exponential_distribution<float> spread(1.f);
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.set(x, y,
              Rgb{0.2f + 0.6f * float(x) / float(width), 0.3f + 0.4f * float(y) / float(height), 0.5f} *
                  spread(rng));
  return img;
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

const Denoiser& denoiser() {
  static const Denoiser d;
  return d;
}

void BM_Denoise(benchmark::State& state) {
  const int width = int(state.range(0)), height = int(state.range(1));
  const Image color = noisy_gradient(width, height);
  const Image albedo = filled(width, height, {0.7f, 0.7f, 0.7f});
  const Image normal = filled(width, height, {0.f, 0.f, 1.f});
  DenoiseOptions options;
  options.threads = int(state.range(2));
  Image out = denoiser().run({&color, &albedo, &normal}, options);  // loads the weights, warms oneDNN
  const int64_t output_bytes = int64_t(out.data().size_bytes());
  out = Image();
  int64_t peak = 0;
  double cpu = 0;
  for (auto _ : state) {
    state.PauseTiming();
    out = Image();
    bench::reset_peak();
    const int64_t before = bench::status_bytes("VmRSS");
    const double cpu_before = process_cpu_seconds();
    state.ResumeTiming();
    out = denoiser().run({&color, &albedo, &normal}, options);
    state.PauseTiming();
    cpu += process_cpu_seconds() - cpu_before;
    peak = std::max(peak, bench::status_bytes("VmHWM") - before - output_bytes);
    state.ResumeTiming();
  }
  state.counters["process_cpu_s"] = cpu / double(state.iterations());
  state.counters["peak_MB"] = double(peak) / (1 << 20);
  state.counters["admitted_MB"] = double(Denoiser::working_bytes(width, height)) / (1 << 20);
  state.counters["Mpixel/s"] = benchmark::Counter(double(width) * height * 1e-6 * double(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

BENCHMARK(BM_Denoise)
    ->ArgsProduct({{512}, {512}, {1, 2}})
    ->Args({1024, 1024, 1})
    ->Args({1024, 1024, 2})
    ->Args({1920, 1080, 1})
    ->Args({1920, 1080, 2})
    ->ArgNames({"width", "height", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

BENCHMARK(BM_Denoise)
    ->Name("Large")
    ->Args({4096, 4096, 2})
    ->ArgNames({"width", "height", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
}  // namespace lp::denoise

BENCHMARK_MAIN();

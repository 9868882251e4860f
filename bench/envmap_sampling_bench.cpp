// Env map sampling: distribution build, one sample, and batches of 1e6 samples, for our two-level
// inverse-CDF sampler, the O(1) alias table, and a plain two-level binary-search sampler (vectors of
// CDFs, std::upper_bound) as the baseline. Maps: a real 1024 x 512 map and the same map enlarged to
// 4096 x 2048 and 8192 x 4096.
// Aims (issue 2): 8192 x 4096 build <= 150 ms on 2 cores; batch sampling >= 5x the baseline at
// 4096 x 2048. Run: ./build/bin/envmap_sampling_bench (see bench/README.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "bench_data.hpp"
#include "engine/core/rng.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/envmap/sample_set.hpp"
#include "engine/image/image_io.hpp"

namespace lp {
namespace {

const EnvMap& forest(int width) {
  static std::map<int, std::unique_ptr<EnvMap>> maps;
  auto& slot = maps[width];
  if (!slot) {
    Image image = read_image_file(bench::envmap_path("forest.exr")).image;
    if (width != image.width()) image = resize_box(image, width, width / 2);
    slot = std::make_unique<EnvMap>(std::move(image));
  }
  return *slot;
}

// The baseline: what a first implementation looks like (pbrt-v3 style, per-row vectors).
class BaselineSampler {
 public:
  explicit BaselineSampler(const EnvMap& map) : map_(map), w_(map.width()), h_(map.height()) {
    std::vector<float> row_sum(static_cast<size_t>(h_));
    rows_.resize(size_t(h_));
    for (int y = 0; y < h_; ++y) {
      const float s = float(std::sin(kPi * (y + 0.5) / h_));
      auto& cdf = rows_[size_t(y)];
      cdf.resize(size_t(w_) + 1);
      func_.emplace_back(size_t(w_));
      for (int x = 0; x < w_; ++x) {
        func_[size_t(y)][size_t(x)] = luminance(map.image().at(x, y), LuminanceMode::Average) * s;
        cdf[size_t(x) + 1] = cdf[size_t(x)] + func_[size_t(y)][size_t(x)];
      }
      row_sum[size_t(y)] = cdf.back();
      for (float& c : cdf) c /= row_sum[size_t(y)];
    }
    marginal_.resize(size_t(h_) + 1);
    for (int y = 0; y < h_; ++y) marginal_[size_t(y) + 1] = marginal_[size_t(y)] + row_sum[size_t(y)];
    total_ = marginal_.back();
    for (float& c : marginal_) c /= total_;
  }

  EnvSample sample(float u1, float u2) const {
    const int y = std::clamp(
        int(std::upper_bound(marginal_.begin(), marginal_.end(), u2) - marginal_.begin()) - 1, 0, h_ - 1);
    const auto& cdf = rows_[size_t(y)];
    const int x = std::clamp(int(std::upper_bound(cdf.begin(), cdf.end(), u1) - cdf.begin()) - 1, 0, w_ - 1);
    EnvSample s;
    s.pixel_x = x, s.pixel_y = y;
    s.u = (float(x) + (u1 - cdf[size_t(x)]) / (cdf[size_t(x) + 1] - cdf[size_t(x)])) / float(w_);
    s.v = (float(y) + (u2 - marginal_[size_t(y)]) / (marginal_[size_t(y) + 1] - marginal_[size_t(y)])) /
          float(h_);
    s.theta = s.v * kPiF, s.phi = s.u * 2 * kPiF;
    s.direction = latlong::direction_from_angles(s.theta, s.phi);
    const float density = func_[size_t(y)][size_t(x)] * float(w_) * float(h_) / total_;
    s.pdf = density / (2 * kPiF * kPiF * std::max(std::sin(s.theta), 1e-7f));
    s.radiance = map_.image().at(x, y);
    return s;
  }

 private:
  const EnvMap& map_;
  int w_, h_;
  float total_ = 0;
  std::vector<std::vector<float>> rows_, func_;
  std::vector<float> marginal_;
};

constexpr int kBatch = 1'000'000;

void BM_DistributionBuild(benchmark::State& state) {
  const EnvMap& map = forest(int(state.range(0)));
  for (auto _ : state) {
    EnvMapSampler sampler(map, LuminanceMode::Average);
    benchmark::DoNotOptimize(sampler.distribution().total_weight());
  }
  state.counters["pixels"] = double(map.image().pixel_count());
}
BENCHMARK(BM_DistributionBuild)->Arg(1024)->Arg(8192)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AliasTableBuild(benchmark::State& state) {
  const EnvMap& map = forest(int(state.range(0)));
  const auto sampler = map.sampler(LuminanceMode::Average);
  for (auto _ : state) {
    AliasTable2D table(sampler->distribution());
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_AliasTableBuild)->Arg(1024)->Arg(8192)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BaselineBuild(benchmark::State& state) {
  const EnvMap& map = forest(int(state.range(0)));
  for (auto _ : state) {
    BaselineSampler b(map);
    benchmark::DoNotOptimize(&b);
  }
}
BENCHMARK(BM_BaselineBuild)->Arg(1024)->Arg(8192)->Unit(benchmark::kMillisecond)->UseRealTime();

// Batches of 1e6 samples on one thread; time per sample is reported as ns/item.
template <class Draw>
void run_batch(benchmark::State& state, Draw draw) {
  for (auto _ : state) {
    float acc = 0;
    for (int i = 0; i < kBatch; ++i) {
      Rng rng(1, uint64_t(i));
      const EnvSample s = draw(rng);
      acc += s.pdf + s.radiance.x;
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

void BM_BatchBaseline(benchmark::State& state) {
  static std::map<int, std::unique_ptr<BaselineSampler>> cache;
  auto& b = cache[int(state.range(0))];
  if (!b) b = std::make_unique<BaselineSampler>(forest(int(state.range(0))));
  run_batch(state, [&](Rng& rng) { return b->sample(rng.uniform_float(), rng.uniform_float()); });
}
BENCHMARK(BM_BatchBaseline)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BatchInverseCdf(benchmark::State& state) {
  const auto sampler = forest(int(state.range(0))).sampler(LuminanceMode::Average);
  run_batch(state, [&](Rng& rng) { return sampler->sample(rng.uniform_float(), rng.uniform_float()); });
}
BENCHMARK(BM_BatchInverseCdf)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BatchAlias(benchmark::State& state) {
  const auto sampler = forest(int(state.range(0))).sampler(LuminanceMode::Average);
  const auto table = sampler->alias_table();  // built outside the timing
  run_batch(state, [&](Rng& rng) {
    const uint64_t a = rng.next_u64(), b = rng.next_u64();
    return sampler->sample_alias(*table, a, b, rng.uniform_float(), rng.uniform_float());
  });
}
BENCHMARK(BM_BatchAlias)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

// The alias table in prefetched blocks, one thread (what generate_samples does per task).
void BM_BatchAliasPrefetched(benchmark::State& state) {
  const auto sampler = forest(int(state.range(0))).sampler(LuminanceMode::Average);
  const auto table = sampler->alias_table();
  std::vector<EnvMapSampler::AliasBits> bits(kBatch);
  std::vector<EnvSample> out(kBatch);
  for (auto _ : state) {
    for (int i = 0; i < kBatch; ++i) {
      Rng rng(1, uint64_t(i));
      bits[size_t(i)] = {rng.next_u64(), rng.next_u64(), rng.uniform_float(), rng.uniform_float()};
    }
    sampler->sample_alias(*table, bits, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_BatchAliasPrefetched)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

// What the server does: generate_samples of a whole set (parallel over the machine's cores).
void BM_GenerateSet(benchmark::State& state) {
  const auto sampler = forest(int(state.range(0))).sampler(LuminanceMode::Average);
  const auto strategy = static_cast<SampleStrategy>(state.range(1));
  std::vector<EnvSample> out(kBatch);
  generate_samples(*sampler, {strategy, kBatch, 1}, 0, std::span(out).first(1));
  for (auto _ : state) generate_samples(*sampler, {strategy, kBatch, 1}, 0, out);
  state.SetItemsProcessed(state.iterations() * kBatch);
  state.SetLabel(enum_name(strategy));
}
BENCHMARK(BM_GenerateSet)
    ->ArgsProduct({{1024, 4096}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One sample at a time (latency), cycling through pre-drawn random numbers.
void BM_OneSample(benchmark::State& state) {
  const auto sampler = forest(int(state.range(0))).sampler(LuminanceMode::Average);
  Rng rng(3, 0);
  for (auto _ : state) benchmark::DoNotOptimize(sampler->sample(rng.uniform_float(), rng.uniform_float()));
}
BENCHMARK(BM_OneSample)->Arg(1024)->Arg(4096);

}  // namespace
}  // namespace lp

BENCHMARK_MAIN();

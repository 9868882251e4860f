#include "engine/envmap/sample_set.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/sampling/sobol_2d.hpp"

namespace lp {

// N points in ny = round(sqrt(N)) bands of u2; band j holds n_j = N/ny or N/ny + 1 cells of width
// 1/n_j, and is n_j/N high, so every cell has area exactly 1/N (unbiased with equal weights).
Point2 stratified_point(uint64_t count, uint64_t seed, uint64_t index) {
  const uint64_t bands = std::max<uint64_t>(1, uint64_t(std::llround(std::sqrt(double(count)))));
  const uint64_t base = count / bands, extra = count % bands;  // the first `extra` bands hold base + 1
  uint64_t band, column, in_band;
  if (index < extra * (base + 1)) {
    band = index / (base + 1), column = index % (base + 1), in_band = base + 1;
  } else {
    const uint64_t rest = index - extra * (base + 1);
    band = extra + rest / base, column = rest % base, in_band = base;
  }
  const uint64_t before = band * base + std::min(band, extra);  // cells in earlier bands
  Rng rng(seed, index);
  const double j1 = rng.uniform_double(), j2 = rng.uniform_double();
  const double u1 = (double(column) + j1) / double(in_band);
  const double u2 = (double(before) + j2 * double(in_band)) / double(count);
  return {std::min(float(u1), kOneMinusEpsilon), std::min(float(u2), kOneMinusEpsilon)};
}

Point2 sobol_point(uint64_t seed, uint64_t index) {
  const auto i = uint32_t(index);
  const auto s0 = uint32_t(mix64(seed ^ 0x5851f42d4c957f2dULL)),
             s1 = uint32_t(mix64(seed ^ 0x14057b7ef767814fULL));
  return {sobol::to_unit_float(sobol::owen_scramble(sobol::dimension0(i), s0)),
          sobol::to_unit_float(sobol::owen_scramble(sobol::dimension1(i), s1))};
}

namespace {

// Stratified and sobol points through the inverse CDF.
EnvSample one_sample(const EnvMapSampler& sampler, const SampleSetSpec& spec, uint64_t index) {
  switch (spec.strategy) {
    case SampleStrategy::Independent:
      break;  // batched: generate_independent
    case SampleStrategy::Stratified: {
      const Point2 p = stratified_point(spec.count, spec.seed, index);
      return sampler.sample(p.x, p.y);
    }
    case SampleStrategy::Sobol: {
      const Point2 p = sobol_point(spec.seed, index);
      return sampler.sample(p.x, p.y);
    }
  }
  return {};
}

// Independent samples go through the alias table in blocks, with the bits drawn first.
void generate_independent(const EnvMapSampler& sampler, const AliasTable2D& alias, uint64_t seed,
                          uint64_t first, std::span<EnvSample> out) {
  std::vector<EnvMapSampler::AliasBits> bits(out.size());
  for (size_t k = 0; k < out.size(); ++k) {
    Rng rng(seed, first + k);
    bits[k].r_row = rng.next_u64();
    bits[k].r_col = rng.next_u64();
    bits[k].fu = rng.uniform_float();
    bits[k].fv = rng.uniform_float();
  }
  sampler.sample_alias(alias, bits, out);
}

}  // namespace

void generate_samples(const EnvMapSampler& sampler, const SampleSetSpec& spec, uint64_t first,
                      std::span<EnvSample> out, const AliasTable2D* alias) {
  if (spec.strategy == SampleStrategy::Sobol && spec.count > (uint64_t{1} << 32))
    throw Error(ErrorKind::InvalidArgument, "sobol sets hold at most 2^32 samples");
  if (spec.strategy == SampleStrategy::Independent) {
    std::shared_ptr<const AliasTable2D> held;
    if (!alias) {
      held = sampler.alias_table();
      alias = held.get();
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, out.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& r) {
                        generate_independent(sampler, *alias, spec.seed, first + r.begin(),
                                             out.subspan(r.begin(), r.size()));
                      });
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, out.size(), 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t k = r.begin(); k != r.end(); ++k)
                        out[k] = one_sample(sampler, spec, first + k);
                    });
}

}  // namespace lp

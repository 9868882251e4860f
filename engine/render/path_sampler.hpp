#pragma once
// The random numbers of one camera sample: each 1D or 2D request is the next "dimension" of a padded,
// shuffled, Owen-scrambled Sobol (0,2)-sequence (Burley 2020): the points of one dimension pair over the
// samples of a pixel form a low-discrepancy net, and different pairs are decorrelated by independent
// scrambles and index shuffles. A pure function of (seed, pixel, sample index, dimension), so images
// are deterministic whatever the thread schedule.
#include <cstdint>

#include "engine/core/point2.hpp"
#include "engine/core/rng.hpp"
#include "engine/sampling/sobol_2d.hpp"

namespace lp::render {

namespace detail {
// reverse_bits(sobol::dimension1(i)) by bytes: the map is linear over XOR, so four table lookups.
struct ReversedDimension1 {
  uint32_t table[4][256];
  constexpr ReversedDimension1() : table{} {
    for (uint32_t b = 0; b < 4; ++b)
      for (uint32_t v = 0; v < 256; ++v) table[b][v] = sobol::reverse_bits(sobol::dimension1(v << (8 * b)));
  }
  uint32_t operator()(uint32_t i) const {
    return table[0][i & 0xff] ^ table[1][(i >> 8) & 0xff] ^ table[2][(i >> 16) & 0xff] ^ table[3][i >> 24];
  }
};
inline constexpr ReversedDimension1 kReversedDimension1{};
}  // namespace detail

class PathSampler {
 public:
  PathSampler(uint64_t seed, uint64_t pixel, uint32_t sample_index)
      : pixel_seed_(mix64(seed ^ mix64(pixel ^ 0x5851f42d4c957f2dULL))),
        reversed_index_(sobol::reverse_bits(sample_index)) {}

  // Owen scrambling is reverse(LK(reverse(x))); the reversals of Sobol dimension 0 and of the index
  // cancel, so each coordinate costs one hash and one reversal.
  Point2 get_2d() {
    const uint64_t h = next_hash();
    const uint32_t index = shuffled_index(h);
    const uint32_t y = sobol::reverse_bits(
        sobol::laine_karras_permutation(detail::kReversedDimension1(index), uint32_t(mix64(h))));
    return {first_coordinate(index, h), sobol::to_unit_float(y)};
  }
  // The x of the next get_2d(), without the work of its y.
  float get_1d() {
    const uint64_t h = next_hash();
    return first_coordinate(shuffled_index(h), h);
  }

 private:
  uint64_t next_hash() { return mix64(pixel_seed_ + 0x9e3779b97f4a7c15ULL * ++dimension_); }
  uint32_t shuffled_index(uint64_t h) const {
    return sobol::reverse_bits(sobol::laine_karras_permutation(reversed_index_, uint32_t(h)));
  }
  static float first_coordinate(uint32_t index, uint64_t h) {
    return sobol::to_unit_float(
        sobol::reverse_bits(sobol::laine_karras_permutation(index, uint32_t(h >> 32))));
  }

  uint64_t pixel_seed_;
  uint32_t reversed_index_;
  uint32_t dimension_ = 0;
};

}  // namespace lp::render

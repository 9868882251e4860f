#pragma once
// The first two dimensions of the Sobol sequence (a (0,2)-sequence in base 2) with hash-based
// Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling"): randomised per seed,
// still a low-discrepancy net for every power-of-two prefix.
#include <cstdint>

namespace lp::sobol {

constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Dimension 0: the van der Corput sequence (bits of the index, reversed).
constexpr uint32_t dimension0(uint32_t index) { return reverse_bits(index); }

// Dimension 1: generator matrix from the primitive polynomial x + 1: v1 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1).
constexpr uint32_t dimension1(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index; index >>= 1, v ^= v >> 1)
    if (index & 1) result ^= v;
  return result;
}

// A hash whose low bits depend only on lower bits of the input: applied to reversed bits it permutes
// each digit depending only on the digits above it, which is Owen scrambling.
constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

constexpr uint32_t owen_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// A 32-bit fixed-point value to a float in [0, 1).
constexpr float to_unit_float(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

}  // namespace lp::sobol

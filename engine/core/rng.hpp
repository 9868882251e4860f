#pragma once
// Counter-based random numbers: sample i of a seeded stream is a pure function of (seed, i),
// so any chunk of a sample set can be generated on any thread and the output is reproducible.
#include <cstdint>

#include "engine/core/constants.hpp"

namespace lp {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A small sequential generator for one sample's dimensions, seeded from (seed, index).
class Rng {
 public:
  constexpr Rng(uint64_t seed, uint64_t index) : state_(mix64(seed ^ mix64(index + 0x9e3779b97f4a7c15ULL))) {}

  constexpr uint64_t next_u64() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix64(state_);
  }
  // Uniform in [0, 1) with 24 random bits.
  constexpr float uniform_float() { return static_cast<float>(next_u64() >> 40) * 0x1p-24f; }
  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform_double() { return static_cast<double>(next_u64() >> 11) * 0x1p-53; }

 private:
  uint64_t state_;
};

}  // namespace lp

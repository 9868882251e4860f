#pragma once
// The body of a decoder fuzz target: decode the bytes under small limits; lp::Error is a clean refusal,
// anything else (a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/core/error.hpp"
#include "engine/image/image_io.hpp"

namespace lp::fuzz {

inline ImageLimits fuzz_limits() {
  ImageLimits limits;
  limits.max_pixels = int64_t{1} << 20;  // enough for every structure, small enough to run fast
  return limits;
}

template <class Decode>
int decode(const uint8_t* data, size_t size, Decode&& decode) {
  try {
    decode(std::span<const uint8_t>(data, size), fuzz_limits());
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace lp::fuzz

#pragma once
// How texture coordinates outside [0, 1) find a texel: glTF's sampler wrap modes.
#include <array>
#include <cmath>

#include "engine/core/enum_table.hpp"

namespace lp {

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };

constexpr auto enum_entries(WrapMode) {
  return std::to_array<EnumEntry<WrapMode>>({{WrapMode::Repeat, "repeat"},
                                             {WrapMode::ClampToEdge, "clamp_to_edge"},
                                             {WrapMode::MirroredRepeat, "mirrored_repeat"}});
}

// The wrap modes of a glTF sampler: s along u (columns), t along v (rows).
struct TextureSampler {
  WrapMode wrap_s = WrapMode::Repeat;
  WrapMode wrap_t = WrapMode::Repeat;
  bool operator==(const TextureSampler&) const = default;
};

// A coordinate brought into a bounded range before it becomes a texel index: [0, 1) for repeat,
// [0, 2) for mirrored repeat, [-1, 2] for clamp (enough for the half-texel filter taps). NaN gives 0.
inline float reduce_coordinate(float u, WrapMode mode) {
  if (!std::isfinite(u)) return 0.0f;
  switch (mode) {
    case WrapMode::Repeat:
      return u - std::floor(u);
    case WrapMode::MirroredRepeat:
      return u - 2.0f * std::floor(0.5f * u);
    case WrapMode::ClampToEdge:
      break;
  }
  return u < -1.0f ? -1.0f : (u > 2.0f ? 2.0f : u);
}

// The texel a possibly outside index `i` of a row or column of `n` texels reads.
inline int wrap_texel(int i, int n, WrapMode mode) {
  switch (mode) {
    case WrapMode::Repeat:
      return ((i % n) + n) % n;
    case WrapMode::MirroredRepeat: {
      const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
    case WrapMode::ClampToEdge:
      break;
  }
  return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

}  // namespace lp

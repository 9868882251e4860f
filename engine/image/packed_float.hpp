#pragma once
// GL_R11F_G11F_B10F texels: three unsigned floats in 32 bits, red in bits 0-10, green in 11-21, blue in
// 22-31 (GL's UNSIGNED_INT_10F_11F_11F_REV). Each has a 5-bit exponent of bias 15 and no sign; red and
// green a 6-bit mantissa, blue a 5-bit one. The conversion follows the OpenGL specification (4.6,
// 2.3.4.3-4): negative values and -inf become 0, NaN stays a NaN, +inf stays infinite, and a finite value
// is rounded to the closest representable finite value (so a value over the largest finite one, 65024 for
// 11 bits and 64512 for 10, becomes it). A tie rounds away from zero, as Filament's cmgen rounds.
#include <bit>
#include <cmath>
#include <cstdint>

#include "engine/core/vec3.hpp"

namespace lp {

inline constexpr int kPackedFloatExponentBias = 15;

// The bits of `value` as an unsigned float of `mantissa_bits` (6 or 5) mantissa bits.
constexpr uint32_t pack_unsigned_float(float value, int mantissa_bits) {
  const uint32_t infinity = 31u << mantissa_bits;
  const uint32_t largest = infinity - 1u;  // exponent 30, mantissa all ones
  if (value != value) return infinity | (1u << (mantissa_bits - 1));
  if (!(value > 0.0f)) return 0u;
  if (value == INFINITY) return infinity;
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  const int exponent = int(bits >> 23) - 127 + kPackedFloatExponentBias;
  if ((bits >> 23) == 0) return 0u;  // a float32 denormal is far below half the smallest denormal here
  const uint32_t significand = (bits & 0x7FFFFFu) | 0x800000u;
  // Normal results keep the significand's top mantissa_bits + 1 bits; denormal ones (exponent < 1) shift
  // further, by one more bit per step below the smallest normal exponent.
  const int shift = 23 - mantissa_bits + (exponent < 1 ? 1 - exponent : 0);
  if (shift > 24) return 0u;
  const uint32_t rounded = (significand + (1u << (shift - 1))) >> shift;
  if (exponent < 1) return rounded;  // a carry into bit mantissa_bits makes the smallest normal, as it should
  const uint32_t carry = rounded >> (mantissa_bits + 1);
  const uint32_t packed =
      (uint32_t(exponent) + carry) << mantissa_bits | ((rounded >> carry) & ((1u << mantissa_bits) - 1u));
  return packed > largest ? largest : packed;
}

inline float unpack_unsigned_float(uint32_t bits, int mantissa_bits) {
  const uint32_t exponent = bits >> mantissa_bits;
  const uint32_t mantissa = bits & ((1u << mantissa_bits) - 1u);
  const float unit = float(1u << mantissa_bits);
  if (exponent == 31) return mantissa ? NAN : INFINITY;
  if (exponent == 0) return std::ldexp(float(mantissa) / unit, 1 - kPackedFloatExponentBias);
  return std::ldexp(1.0f + float(mantissa) / unit, int(exponent) - kPackedFloatExponentBias);
}

inline constexpr float kLargestR11f = 65024.0f;
inline constexpr float kLargestB10f = 64512.0f;

constexpr uint32_t pack_r11g11b10f(Rgb c) {
  return pack_unsigned_float(c.x, 6) | pack_unsigned_float(c.y, 6) << 11 | pack_unsigned_float(c.z, 5) << 22;
}

inline Rgb unpack_r11g11b10f(uint32_t texel) {
  return {unpack_unsigned_float(texel & 0x7FFu, 6), unpack_unsigned_float((texel >> 11) & 0x7FFu, 6),
          unpack_unsigned_float(texel >> 22, 5)};
}

}  // namespace lp

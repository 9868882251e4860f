// R11F_G11F_B10F packing: bit patterns worked out by hand from the format (5-bit exponent of bias 15,
// 6- or 5-bit mantissa, no sign), the OpenGL specification's special values, rounding to the nearest
// representable value (ties away from zero), and round trips of every finite code.
#include "engine/image/packed_float.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lp {
namespace {

TEST(PackedFloat, KnownBitPatterns) {
  EXPECT_EQ(pack_unsigned_float(1.0f, 6), 15u << 6);              // 0x3C0
  EXPECT_EQ(pack_unsigned_float(1.0f, 5), 15u << 5);              // 0x1E0
  EXPECT_EQ(pack_unsigned_float(0.5f, 6), 14u << 6);              // 0x380
  EXPECT_EQ(pack_unsigned_float(1.5f, 6), (15u << 6) | 32u);      // mantissa 0.5 = 100000b
  EXPECT_EQ(pack_unsigned_float(3.0f, 5), (16u << 5) | 16u);      // 1.5 x 2
  EXPECT_EQ(pack_unsigned_float(kLargestR11f, 6), 0x7BFu);        // exponent 30, mantissa 111111b
  EXPECT_EQ(pack_unsigned_float(kLargestB10f, 5), 0x3DFu);        // exponent 30, mantissa 11111b
  EXPECT_EQ(pack_unsigned_float(std::ldexp(1.0f, -14), 6), 64u);  // the smallest normal
  EXPECT_EQ(pack_unsigned_float(std::ldexp(1.0f, -20), 6), 1u);   // the smallest denormal: 2^-14 / 64
  EXPECT_EQ(pack_unsigned_float(std::ldexp(1.0f, -19), 5), 1u);   // 2^-14 / 32
  EXPECT_EQ(pack_unsigned_float(std::ldexp(3.0f, -20), 6), 3u);
  EXPECT_EQ(pack_r11g11b10f({1.0f, 0.5f, 2.0f}), (15u << 6) | (14u << 6) << 11 | (16u << 5) << 22);
}

TEST(PackedFloat, SpecialValuesAsTheGlSpecificationConvertsThem) {
  EXPECT_EQ(pack_unsigned_float(0.0f, 6), 0u);
  EXPECT_EQ(pack_unsigned_float(-0.0f, 6), 0u);
  EXPECT_EQ(pack_unsigned_float(-1.0f, 6), 0u);
  EXPECT_EQ(pack_unsigned_float(-INFINITY, 5), 0u);
  EXPECT_EQ(pack_unsigned_float(INFINITY, 6), 31u << 6);
  EXPECT_EQ(pack_unsigned_float(INFINITY, 5), 31u << 5);
  EXPECT_TRUE(std::isnan(unpack_unsigned_float(pack_unsigned_float(NAN, 6), 6)));
  EXPECT_TRUE(std::isnan(unpack_unsigned_float(pack_unsigned_float(NAN, 5), 5)));
  // Finite values over the largest finite one round to it, never to infinity.
  EXPECT_EQ(pack_unsigned_float(1e30f, 6), 0x7BFu);
  EXPECT_EQ(pack_unsigned_float(65535.0f, 6), 0x7BFu);
  EXPECT_EQ(pack_unsigned_float(65535.0f, 5), 0x3DFu);
  EXPECT_EQ(pack_unsigned_float(std::ldexp(1.0f, -22), 6), 0u);  // under half the smallest denormal
  EXPECT_EQ(pack_unsigned_float(std::numeric_limits<float>::denorm_min(), 6), 0u);
}

TEST(PackedFloat, RoundsToTheNearestAndTiesAwayFromZero) {
  const float ulp = std::ldexp(1.0f, -6);  // between 1 and 2 for 6 mantissa bits
  EXPECT_EQ(pack_unsigned_float(1.0f + 0.49f * ulp, 6), 0x3C0u);
  EXPECT_EQ(pack_unsigned_float(1.0f + 0.5f * ulp, 6), 0x3C1u);
  EXPECT_EQ(pack_unsigned_float(1.0f + 1.49f * ulp, 6), 0x3C1u);
  EXPECT_EQ(pack_unsigned_float(2.0f - 0.5f * ulp, 6), 16u << 6);  // the carry into the exponent
  EXPECT_EQ(pack_unsigned_float(std::ldexp(2.5f, -20), 6), 3u);    // a denormal tie
  EXPECT_EQ(pack_unsigned_float(std::ldexp(1.0f, -14) * (1.0f - 0.25f / 64), 6), 64u);  // up to normal
}

TEST(PackedFloat, EveryFiniteCodeRoundTrips) {
  for (const int bits : {6, 5})
    for (uint32_t code = 0; code < (31u << bits); ++code) {
      const float v = unpack_unsigned_float(code, bits);
      ASSERT_EQ(pack_unsigned_float(v, bits), code) << "code " << code << " of " << bits << " bits, " << v;
    }
  EXPECT_EQ(unpack_unsigned_float(0x3C0u, 6), 1.0f);
  EXPECT_EQ(unpack_unsigned_float(1u, 5), std::ldexp(1.0f, -19));
  EXPECT_EQ(unpack_unsigned_float(0x7BFu, 6), kLargestR11f);
}

// Within range, the relative error is at most half a unit in the last place: 2^-7 for 11 bits, 2^-6 for
// 10; and the packed value is the nearest of its two neighbours.
TEST(PackedFloat, RandomValuesAreWithinHalfAnUlp) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> log2_value(-14.0f, 15.9f);
  for (int i = 0; i < 100000; ++i) {
    const float v = std::exp2(log2_value(rng));
    const Rgb back = unpack_r11g11b10f(pack_r11g11b10f({v, v, v}));
    ASSERT_LE(std::abs(back.x - v), v * std::ldexp(1.0f, -7)) << v;
    ASSERT_EQ(back.y, back.x);
    ASSERT_LE(std::abs(back.z - v), v * std::ldexp(1.0f, -6)) << v;
  }
}

}  // namespace
}  // namespace lp

// sincos_turns against the double-precision sin and cos: the absolute error bound of its header over
// several turns, the relative precision of sin near 0, and exact values at the quarter turns.
#include "engine/core/fast_sincos.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/rng.hpp"

namespace lp {
namespace {

TEST(FastSinCos, WithinItsBoundOfTheExactValues) {
  Rng rng(12, 0);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    const float t = 4 * rng.uniform_float() - 2;
    const double angle = 2 * std::numbers::pi * double(t);
    const SinCos sc = sincos_turns(t);
    worst = std::max({worst, std::abs(sc.sin - std::sin(angle)), std::abs(sc.cos - std::cos(angle))});
  }
  EXPECT_LT(worst, 1.2e-7);
}

TEST(FastSinCos, SmallAnglesKeepTheirRelativePrecision) {
  for (float t = 1e-30f; t < 1e-2f; t *= 1.7f) {
    const double angle = 2 * std::numbers::pi * double(t);
    EXPECT_NEAR(sincos_turns(t).sin / std::sin(angle), 1.0, 2e-7) << t;
    EXPECT_NEAR(sincos_turns(-t).sin / std::sin(-angle), 1.0, 2e-7) << t;
  }
}

TEST(FastSinCos, QuarterTurnsAreExact) {
  const float turns[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f, -0.25f, -0.5f};
  const float sines[] = {0, 1, 0, -1, 0, -1, 0}, cosines[] = {1, 0, -1, 0, 1, 0, -1};
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(std::abs(sincos_turns(turns[i]).sin), std::abs(sines[i])) << turns[i];
    EXPECT_EQ(sincos_turns(turns[i]).sin + 0.0f, sines[i]) << turns[i];
    EXPECT_EQ(sincos_turns(turns[i]).cos + 0.0f, cosines[i]) << turns[i];
  }
}

}  // namespace
}  // namespace lp

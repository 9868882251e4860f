// fast_atan2 against the double-precision atan2: the absolute error bound of its header over the whole
// circle, the relative precision of small angles, and the signs and quadrants std::atan2 gives.
#include "engine/core/fast_atan2.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/rng.hpp"

namespace lp {
namespace {

TEST(FastAtan2, WithinItsBoundOfTheExactAngle) {
  Rng rng(11, 0);
  double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    float y = 2 * rng.uniform_float() - 1, x = 2 * rng.uniform_float() - 1;
    if (i % 3 == 0) y *= 1e-4f;  // near the x axis, where the result crosses +-pi
    worst = std::max(worst, std::abs(double(fast_atan2(y, x)) - std::atan2(double(y), double(x))));
  }
  EXPECT_LT(worst, 3e-7);
}

TEST(FastAtan2, SmallAnglesKeepTheirRelativePrecision) {
  for (float y = 1e-30f; y < 1e-2f; y *= 1.7f)
    EXPECT_NEAR(fast_atan2(y, 1.0f) / std::atan2(double(y), 1.0), 1.0, 1e-7) << y;
}

TEST(FastAtan2, SignsAndAxesAsStdAtan2) {
  const float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 3.0f, -0.25f};
  for (float y : values)
    for (float x : values) {
      const float expected = std::atan2(y, x), got = fast_atan2(y, x);
      EXPECT_NEAR(got, expected, 3e-7f) << y << " " << x;
      EXPECT_EQ(std::signbit(got), std::signbit(expected)) << y << " " << x;
    }
  EXPECT_EQ(fast_atan2(0.0f, 0.0f), 0.0f);
}

}  // namespace
}  // namespace lp

#pragma once
// atan2 in float without a call into libm: the octant reduced to a ratio in [0, 1], then a polynomial
// (Abramowitz & Stegun 4.4.49, |error| <= 2e-8 rad in exact arithmetic). In float the result is within
// 3e-7 rad of the true angle, keeps its relative precision near 0 (the polynomial is a * (1 + ...)),
// and costs a division and a few multiply-adds where glibc's atan2f takes several times as long.
#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

// atan(a) for a in [0, 1].
inline float atan_unit(float a) {
  const float s = a * a;
  float p = 0.0028662257f;
  p = p * s - 0.0161657367f;
  p = p * s + 0.0429096138f;
  p = p * s - 0.0752896400f;
  p = p * s + 0.1065626393f;
  p = p * s - 0.1420889944f;
  p = p * s + 0.1999355085f;
  p = p * s - 0.3333314528f;
  return a + a * (p * s);
}

// The angle of (x, y) in [-pi, pi], signs as std::atan2 for finite arguments (atan2(+-0, x >= 0) = +-0,
// atan2(+-0, x < 0) = +-pi); 0 for (0, 0).
inline float fast_atan2(float y, float x) {
  const float ax = std::abs(x), ay = std::abs(y);
  const float hi = std::max(ax, ay), lo = std::min(ax, ay);
  float r = hi > 0 ? atan_unit(lo / hi) : 0.0f;
  if (ay > ax) r = 0.5f * kPiF - r;
  if (std::signbit(x)) r = kPiF - r;
  return std::copysign(r, y);
}

}  // namespace lp

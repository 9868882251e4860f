#pragma once
// sin and cos of an angle given in turns (2 pi t radians) without a call into libm: the quadrant is
// taken off exactly (t - q / 4 loses no bits), then Taylor polynomials on [-pi / 4, pi / 4] (degree 9
// and 10, truncation below 3e-9). In float both results are within 1.2e-7 of the true values, sin keeps
// its relative precision near 0, and the pair costs a dozen multiply-adds where glibc's two sincosf
// calls take several times as long. For |t| up to 2^20.
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

struct SinCos {
  float sin, cos;
};

inline SinCos sincos_turns(float t) {
  // The nearest quarter turn, by truncation: std::nearbyint is a call into libm on x86-64's baseline.
  const int q = int(4.0f * t + (t >= 0 ? 0.5f : -0.5f));
  const float x = (t - 0.25f * float(q)) * (2.0f * kPiF);
  const float x2 = x * x;
  float s = 1.0f / 362880.0f;
  s = s * x2 - 1.0f / 5040.0f;
  s = s * x2 + 1.0f / 120.0f;
  s = s * x2 - 1.0f / 6.0f;
  s = x + x * (s * x2);
  float c = -1.0f / 3628800.0f;
  c = c * x2 + 1.0f / 40320.0f;
  c = c * x2 - 1.0f / 720.0f;
  c = c * x2 + 1.0f / 24.0f;
  c = c * x2 - 0.5f;
  c = 1.0f + c * x2;
  // The angle is q quarter turns plus x: rotate (cos x, sin x) by q * 90 degrees.
  const int quadrant = q & 3;
  const float sin_q = quadrant & 1 ? c : s, cos_q = quadrant & 1 ? s : c;
  return {quadrant >= 2 ? -sin_q : sin_q, quadrant == 1 || quadrant == 2 ? -cos_q : cos_q};
}

}  // namespace lp

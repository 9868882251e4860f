#pragma once
#include <numbers>

namespace lp {
inline constexpr double kPi = std::numbers::pi;
inline constexpr float kPiF = std::numbers::pi_v<float>;
// The largest float below 1: uniform samples live in [0, kOneMinusEpsilon].
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
}  // namespace lp

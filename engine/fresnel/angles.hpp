#pragma once
// Degrees <-> radians for the Fresnel tables, with the end points of 0..90 exact: cos_deg(90) is 0, not
// 6.1e-17, so grazing incidence really is grazing.
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

inline double radians(double deg) {
  return deg * (kPi / 180.0);
}
inline double degrees(double rad) {
  return rad * (180.0 / kPi);
}
inline double cos_deg(double deg) {
  return deg == 90.0 ? 0.0 : std::cos(radians(deg));
}

}  // namespace lp

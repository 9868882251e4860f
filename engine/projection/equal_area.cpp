#include "engine/projection/equal_area.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp::equal_area {

// In the quadrant of (|x|, |y|): r = sqrt(1 - |z|) from |z| = 1 - r^2, and the azimuth as a fraction of a
// quarter turn, f = phi / (pi/2), splits r into |v| = f r and |u| = r - |v| (inside the diamond); the
// lower hemisphere mirrors that point across the diamond's edge.
Point2d square(Vec3d d) {
  const double len = length(d);
  const double x = std::abs(d.x) / len, y = std::abs(d.y) / len, z = std::abs(d.z) / len;
  const double r = std::sqrt(std::max(0.0, 1 - z));
  const double f = std::atan2(y, x) / (kPi / 2);
  double v = f * r, u = r - v;
  if (d.z < 0) {
    const double folded_u = 1 - v;
    v = 1 - u;
    u = folded_u;
  }
  return {std::copysign(u, d.x), std::copysign(v, d.y)};
}

Vec3d direction(Point2d uv) {
  const double au = std::abs(uv.x), av = std::abs(uv.y);
  const double signed_distance = 1 - (au + av);  // > 0 inside the diamond
  const double r = 1 - std::abs(signed_distance);
  const double phi = (r == 0 ? 1 : (av - au) / r + 1) * kPi / 4;
  const double z = std::copysign(1 - r * r, signed_distance);
  const double radial = r * std::sqrt(std::max(0.0, 2 - r * r));
  return {std::copysign(std::cos(phi) * radial, uv.x), std::copysign(std::sin(phi) * radial, uv.y), z};
}

}  // namespace lp::equal_area

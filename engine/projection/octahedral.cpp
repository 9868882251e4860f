#include "engine/projection/octahedral.hpp"

#include <cmath>

namespace lp::octahedral {
namespace {

double sign_not_zero(double v) {
  return v < 0 ? -1.0 : 1.0;
}

}  // namespace

Point2d square(Vec3d d) {
  const double n = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  const double x = d.x / n, y = d.y / n;
  if (d.z >= 0) return {x, y};
  return {(1 - std::abs(y)) * sign_not_zero(x), (1 - std::abs(x)) * sign_not_zero(y)};
}

Vec3d octahedron_point(Point2d uv) {
  const double z = 1 - std::abs(uv.x) - std::abs(uv.y);
  if (z >= 0) return {uv.x, uv.y, z};
  return {(1 - std::abs(uv.y)) * sign_not_zero(uv.x), (1 - std::abs(uv.x)) * sign_not_zero(uv.y), z};
}

Vec3d direction(Point2d uv) {
  return normalize(octahedron_point(uv));
}

}  // namespace lp::octahedral

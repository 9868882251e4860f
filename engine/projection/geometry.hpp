#pragma once
// Double-precision points and vectors for the geometry of projections: texel corners, their directions
// and the areas of the pieces a texel is cut into need more than float precision at 8K.
#include <cmath>

#include "engine/core/vec3.hpp"

namespace lp {

struct Vec3d {
  double x = 0, y = 0, z = 0;

  constexpr Vec3d operator+(Vec3d b) const { return {x + b.x, y + b.y, z + b.z}; }
  constexpr Vec3d operator-(Vec3d b) const { return {x - b.x, y - b.y, z - b.z}; }
  constexpr Vec3d operator-() const { return {-x, -y, -z}; }
  constexpr Vec3d operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr bool operator==(const Vec3d&) const = default;
};

constexpr Vec3d operator*(double s, Vec3d v) {
  return v * s;
}
constexpr double dot(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3d v) {
  return std::sqrt(dot(v, v));
}
inline Vec3d normalize(Vec3d v) {
  return v * (1.0 / length(v));
}
// The angle between two directions of any length, accurate for small angles too.
inline double angle_between(Vec3d a, Vec3d b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}
inline Vec3 to_float(Vec3d v) {
  return {float(v.x), float(v.y), float(v.z)};
}
inline Vec3d to_double(Vec3 v) {
  return {v.x, v.y, v.z};
}

// A point of a projection's plane: the square [-1, 1]^2 of a cube face or of the square maps.
struct Point2d {
  double x = 0, y = 0;
};

}  // namespace lp

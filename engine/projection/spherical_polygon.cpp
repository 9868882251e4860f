#include "engine/projection/spherical_polygon.hpp"

#include <cmath>

namespace lp {
namespace {

// atan(y / x) for x > 0, by its series when y / x is small: the triangles of a large map are tiny, and
// the series is then exact to double precision at a fraction of atan2's cost.
double atan_of_ratio(double y, double x) {
  if (x > 0 && std::abs(y) < 1e-2 * x) {
    const double t = y / x, t2 = t * t;
    return t * (1 - t2 * (1.0 / 3 - t2 * (1.0 / 5 - t2 * (1.0 / 7 - t2 / 9))));
  }
  return std::atan2(y, x);
}

// The signed solid angle of the triangle of unit vectors a, b, c (Van Oosterom and Strackee 1983):
// tan(omega / 2) = a . (b x c) / (1 + a.b + b.c + c.a). The triple product is taken of differences,
// which keep their precision for the tiny triangles of a large map.
double triangle_area(Vec3d a, Vec3d b, Vec3d c) {
  const double triple = dot(a, cross(b - a, c - a));
  return 2 * atan_of_ratio(triple, 1 + dot(a, b) + dot(b, c) + dot(c, a));
}

}  // namespace

// A fan of triangles from the corners' mean, which lies inside any polygon this small (a fan from a
// corner would fail for a polygon reaching from one pole to the other).
double spherical_polygon_area(std::span<const Vec3d> corners) {
  if (corners.size() < 3) return 0;
  Vec3d sum;
  for (const Vec3d& c : corners) sum = sum + c;
  const Vec3d apex = dot(sum, sum) > 0 ? normalize(sum) : normalize(corners[0]);
  Vec3d previous = normalize(corners.back());
  double area = 0;
  for (const Vec3d& c : corners) {
    const Vec3d next = normalize(c);
    area += triangle_area(apex, previous, next);
    previous = next;
  }
  return area;
}

void clip_to_hemisphere(std::span<const Vec3d> in, Vec3d normal, SphericalPolygon& out) {
  out.clear();
  const size_t n = in.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3d a = in[i], b = in[(i + 1) % n];
    const double da = dot(a, normal), db = dot(b, normal);
    if (da >= 0) out.push_back(a);
    if ((da < 0) != (db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
}

bool clip_to_hemispheres(std::span<const Vec3d> in, std::initializer_list<Vec3d> normals,
                         SphericalPolygon& out, SphericalPolygon& spare) {
  out.assign(in.begin(), in.end());
  for (const Vec3d normal : normals) {
    clip_to_hemisphere(out, normal, spare);
    std::swap(out, spare);
    if (out.size() < 3) return false;
  }
  return true;
}

}  // namespace lp

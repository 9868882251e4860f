#pragma once
// Lat-long conventions (CONTRIBUTING.md): z up; pixel (x, y) has centre u = (x + 0.5)/W, v = (y + 0.5)/H,
// row 0 at the top; theta = v*pi from +z, phi = u*2*pi;
// direction = (sin theta cos phi, sin theta sin phi, cos theta).
#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/fast_atan2.hpp"
#include "engine/core/fast_sincos.hpp"
#include "engine/core/vec3.hpp"

namespace lp::latlong {

struct Uv {
  float u = 0, v = 0;
};

inline Vec3 direction_from_angles(float theta, float phi) {
  const float s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

// The direction of polar angle theta and azimuth phi, from their sines and cosines.
inline Vec3 direction(SinCos theta, SinCos phi) {
  return {theta.sin * phi.cos, theta.sin * phi.sin, theta.cos};
}

inline Vec3 direction(Uv uv) {
  return direction(sincos_turns(0.5f * uv.v), sincos_turns(uv.u));
}

// sin(theta) of a direction `d` (need not be normalised), with full relative precision near both
// poles, where sin(v * pi) loses it.
inline float sin_theta(Vec3 d) {
  return std::sqrt(d.x * d.x + d.y * d.y) / length(d);
}

// u in [0, 1), v in [0, 1]; `d` need not be normalised (its squared components must not overflow or
// all underflow a float). On every lookup of a path tracer: fast_atan2, within 3e-7 rad.
inline Uv uv(Vec3 d) {
  // atan2 keeps full precision near the poles, where acos(z) loses it.
  const float theta = fast_atan2(std::sqrt(d.x * d.x + d.y * d.y), d.z);
  float phi = fast_atan2(d.y, d.x);
  if (phi < 0) phi += 2.0f * kPiF;
  float u = phi * (0.5f / kPiF);
  if (u >= 1.0f) u = 0.0f;
  return {u, std::min(theta * (1.0f / kPiF), 1.0f)};
}

// The pixel containing (u, v), clamped to the grid.
inline int pixel_x(float u, int width) {
  return std::clamp(int(u * float(width)), 0, width - 1);
}
inline int pixel_y(float v, int height) {
  return std::clamp(int(v * float(height)), 0, height - 1);
}

// Exact solid angle of one pixel of row y: (2 pi / W) * (cos theta_top - cos theta_bottom).
inline double pixel_solid_angle(int y, int width, int height) {
  const double t0 = kPi * y / height, t1 = kPi * (y + 1) / height;
  return (2.0 * kPi / width) * (std::cos(t0) - std::cos(t1));
}

inline double row_centre_theta(int y, int height) {
  return kPi * (y + 0.5) / height;
}

}  // namespace lp::latlong

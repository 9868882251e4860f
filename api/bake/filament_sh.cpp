#include "api/bake/filament_sh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "engine/projection/geometry.hpp"

namespace lp::api {
namespace {

using std::numbers::pi;

// The real SH of sh_basis.hpp as polynomials: Y = k * (its polynomial of the world direction).
const double k0 = 0.5 / std::sqrt(pi);
const double k1 = std::sqrt(3.0) / (2 * std::sqrt(pi));
const double k2 = std::sqrt(15.0) / (2 * std::sqrt(pi));   // xy, yz, xz
const double k20 = std::sqrt(5.0) / (4 * std::sqrt(pi));   // 3 z^2 - 1
const double k22 = std::sqrt(15.0) / (4 * std::sqrt(pi));  // x^2 - y^2

// Coefficients of the polynomial terms for one channel, from SH coefficients c (index l (l + 1) + m),
// with the world direction w = (n.x, -n.z, n.y) substituted. On the sphere, 3 w.z^2 - 1 = 3 n.y^2 - 1
// = -(3 n.z^2 - 1) / 2 - 3 (n.x^2 - n.y^2) / 2 and w.x^2 - w.y^2 = n.x^2 - n.z^2 = -(3 n.z^2 - 1) / 2
// + (n.x^2 - n.y^2) / 2.
std::array<double, 9> polynomial(const std::array<double, 9>& c) {
  return {k0 * c[0],
          k1 * c[2],
          -k1 * c[1],
          k1 * c[3],
          k2 * c[7],
          -k2 * c[5],
          -0.5 * k20 * c[6] - 0.5 * k22 * c[8],
          -k2 * c[4],
          -1.5 * k20 * c[6] + 0.5 * k22 * c[8]};
}

std::array<double, 9> channel(const ShCoefficients& sh, int rgb) {
  std::array<double, 9> c{};
  for (int i = 0; i < 9; ++i) c[size_t(i)] = sh.rgb[size_t(i)][size_t(rgb)];
  return c;
}

// One channel of irradiance as c + b . w + w^T Q w on the unit sphere (Q traceless), w in the world.
struct Quadratic {
  double c = 0;
  Vec3d b;
  double q[3][3] = {};
};

Quadratic quadratic(const ShCoefficients& e, int rgb) {
  const auto at = [&](int l, int m) { return e.rgb[size_t(sh_index(l, m))][size_t(rgb)]; };
  Quadratic f;
  f.c = k0 * at(0, 0);
  f.b = {k1 * at(1, 1), k1 * at(1, -1), k1 * at(1, 0)};
  const double zonal = k20 * at(2, 0), sectoral = k22 * at(2, 2);  // 3z^2 - 1 = 2z^2 - x^2 - y^2 here
  f.q[0][0] = -zonal + sectoral, f.q[1][1] = -zonal - sectoral, f.q[2][2] = 2 * zonal;
  f.q[0][1] = f.q[1][0] = 0.5 * k2 * at(2, -2);
  f.q[1][2] = f.q[2][1] = 0.5 * k2 * at(2, -1);
  f.q[0][2] = f.q[2][0] = 0.5 * k2 * at(2, 1);
  return f;
}

double form(const double q[3][3], const Vec3d& u, const Vec3d& v) {
  const double a[3] = {u.x, u.y, u.z}, b[3] = {v.x, v.y, v.z};
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sum += a[i] * q[i][j] * b[j];
  return sum;
}

// What cmgen's lower bound of a channel needs, in the frame whose z is the linear part's direction u:
// the zonal terms (c, |b| z, Q_uu (3z^2 - 1) / 2), the amplitude m2 of the |m| = 2 terms (times
// 1 - z^2) and d of the |m| = 1 terms (times z sqrt(1 - z^2)). Rotations and reflections keep them.
struct ZonalBound {
  double c, b, zonal2, m2, m1;
};

ZonalBound zonal_bound(const Quadratic& f) {
  const double length = std::sqrt(f.b.x * f.b.x + f.b.y * f.b.y + f.b.z * f.b.z);
  const Vec3d u = length > 0 ? Vec3d{f.b.x / length, f.b.y / length, f.b.z / length} : Vec3d{0, 0, 1};
  const Vec3d helper = std::abs(u.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  Vec3d x{u.y * helper.z - u.z * helper.y, u.z * helper.x - u.x * helper.z, u.x * helper.y - u.y * helper.x};
  const double xl = std::sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
  x = {x.x / xl, x.y / xl, x.z / xl};
  const Vec3d y{u.y * x.z - u.z * x.y, u.z * x.x - u.x * x.z, u.x * x.y - u.y * x.x};
  const double qxx = form(f.q, x, x), qyy = form(f.q, y, y), qxy = form(f.q, x, y);
  const double qxz = form(f.q, x, u), qyz = form(f.q, y, u), quu = form(f.q, u, u);
  return {f.c, length, quu / 2, std::sqrt(0.25 * (qxx - qyy) * (qxx - qyy) + qxy * qxy),
          2 * std::sqrt(qxz * qxz + qyz * qyz)};
}

// cmgen's minimum of a channel windowed by w1, w2 (CubemapSH::windowSH's shmin, in float as there):
// the zonal and |m| = 2 terms minimised over z in closed form, the |m| = 1 terms added by Newton's
// method when the bound could be negative.
float bound_minimum(const ZonalBound& z, double w1, double w2) {
  const float m2max = float(w2 * z.m2);
  const float a = float(3 * w2 * z.zonal2) + m2max;
  const float b = float(w1 * z.b);
  const float c = float(z.c - w2 * z.zonal2) - m2max;
  const float zmin = -b / (2.0f * a);
  const float m0min_z = a * zmin * zmin + b * zmin + c;
  const float m0min = (a > 0 && zmin >= -1 && zmin <= 1) ? m0min_z : std::min(a + b + c, a - b + c);
  const float d = float(w2 * z.m1);
  float minimum = m0min - 0.5f * d;
  if (minimum >= 0) return minimum;
  const auto func = [=](float t) { return (a * t * t + b * t + c) + (d * t * std::sqrt(1 - t * t)); };
  const auto increment = [=](float t) {
    return (t * t - 1) * (d - 2 * d * t * t + (b + 2 * a * t) * std::sqrt(1 - t * t)) /
           (3 * d * t - 2 * d * t * t * t - 2 * a * std::pow(1 - t * t, 1.5f));
  };
  float t = -std::sqrt(0.5f), dt = 0;
  int steps = 0;
  do {
    minimum = func(t);
    dt = increment(t);
    t -= dt;
  } while (std::abs(t) <= 1 && std::abs(dt) > 1e-5f && ++steps < 100);
  if (std::abs(t) > 1) minimum = std::min(func(1), func(-1));
  return minimum;
}

// cmgen's bisection, in its float arithmetic, so that the cut-off lands on the same tenth of a band: for
// each channel in turn, from [3, the cut-off so far].
float auto_cutoff(const ShCoefficients& irradiance) {
  float cutoff = 3 * 4 + 1;
  for (int rgb = 0; rgb < 3; ++rgb) {
    const ZonalBound bound = zonal_bound(quadratic(irradiance, rgb));
    float low = 3, high = cutoff;
    for (int i = 0; i < 16 && low + 0.1f < high; ++i) {
      const float middle = 0.5f * (low + high);
      const bool negative =
          bound_minimum(bound, filament_sh_window(1, middle), filament_sh_window(2, middle)) < 0;
      (negative ? high : low) = middle;
    }
    cutoff = std::min(cutoff, low);
  }
  return cutoff;
}

}  // namespace

double filament_sh_window(int l, double cutoff) {
  if (l == 0) return 1;
  if (l >= cutoff) return 0;
  const double x = pi * l / cutoff;
  return std::pow(std::sin(x) / x, 4);
}

FilamentSh filament_sh(const ShCoefficients& radiance) {
  const ShCoefficients irradiance = sh_irradiance(radiance.truncated(3));
  FilamentSh out;
  out.window_cutoff = auto_cutoff(irradiance);
  std::vector<double> factors;
  for (int l = 0; l < 3; ++l) factors.push_back(filament_sh_window(l, out.window_cutoff) / pi);
  const ShCoefficients diffuse = scaled_by_band(irradiance, factors);
  for (int rgb = 0; rgb < 3; ++rgb) {
    const auto p = polynomial(channel(diffuse, rgb));
    for (size_t i = 0; i < 9; ++i) out.coefficients[i][size_t(rgb)] = p[i];
  }
  return out;
}

std::string filament_sh_text(const FilamentSh& sh) {
  std::ostringstream text;
  for (const ShRgb& c : sh.coefficients)
    text << float(c[0]) << " " << float(c[1]) << " " << float(c[2]) << "\n";
  return text.str();
}

}  // namespace lp::api

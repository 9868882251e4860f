#include "support/sphere_chi_square.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine/core/constants.hpp"

namespace lp::test {
namespace {

constexpr int kThetaCells = 40, kPhiCells = 40;
// Each cell starts as kStart x kStart pieces; a piece is halved at most kDepth times.
constexpr int kStart = 2, kDepth = 8;
// Tolerated error of one cell's probability: absolute, and relative to the cell.
constexpr double kAbsoluteTolerance = 1e-7, kRelativeTolerance = 1e-4;

Vec3 direction(double theta, double phi) {
  const double s = std::sin(theta);
  return {float(s * std::cos(phi)), float(s * std::sin(phi)), float(std::cos(theta))};
}

int cell_of(Vec3 w) {
  const double theta = std::acos(std::clamp(double(w.z), -1.0, 1.0));
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0) phi += 2 * kPi;
  const int i = std::clamp(int(theta / kPi * kThetaCells), 0, kThetaCells - 1);
  const int j = std::clamp(int(phi / (2 * kPi) * kPhiCells), 0, kPhiCells - 1);
  return i * kPhiCells + j;
}

struct Rect {
  double theta0, theta1, phi0, phi1;
};

double value(const DirectionPdf& pdf, double theta, double phi) {
  return double(pdf(direction(theta, phi))) * std::sin(theta);
}

// pdf(w) sin(theta) on the 3 x 3 points of Simpson's rule over a rectangle: its corners, edge midpoints
// and centre. They include the border, so a piece of lobe that only reaches into it is not missed.
using Points = std::array<std::array<double, 3>, 3>;

Points points(const DirectionPdf& pdf, const Rect& r) {
  Points p;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      p[a][b] = value(pdf, r.theta0 + 0.5 * a * (r.theta1 - r.theta0), r.phi0 + 0.5 * b * (r.phi1 - r.phi0));
  return p;
}

double simpson(const Points& p, const Rect& r) {
  static constexpr double kWeight[3] = {1.0, 4.0, 1.0};
  double sum = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) sum += kWeight[a] * kWeight[b] * p[a][b];
  return sum * (r.theta1 - r.theta0) * (r.phi1 - r.phi0) / 36.0;
}

// The integral over r, whose points are p: Simpson's rule on its quarters (a 5 x 5 grid that reuses p),
// refined where it disagrees with the rule on the whole.
double integrate(const DirectionPdf& pdf, const Rect& r, const Points& p, double tolerance, int depth) {
  const double dt = 0.25 * (r.theta1 - r.theta0), dp = 0.25 * (r.phi1 - r.phi0);
  double grid[5][5];
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b)
      grid[a][b] =
          a % 2 == 0 && b % 2 == 0 ? p[a / 2][b / 2] : value(pdf, r.theta0 + a * dt, r.phi0 + b * dp);
  std::array<Rect, 4> quarter;
  std::array<Points, 4> quarter_points;
  double sum = 0;
  for (int k = 0; k < 4; ++k) {
    const int qa = k / 2, qb = k % 2;
    quarter[k] = {r.theta0 + 2 * qa * dt, r.theta0 + 2 * (qa + 1) * dt, r.phi0 + 2 * qb * dp,
                  r.phi0 + 2 * (qb + 1) * dp};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) quarter_points[k][a][b] = grid[2 * qa + a][2 * qb + b];
    sum += simpson(quarter_points[k], quarter[k]);
  }
  const double whole = simpson(p, r);
  if (depth == 0 || std::abs(sum - whole) <= std::max(tolerance, kRelativeTolerance * std::abs(sum)))
    return sum;
  double refined = 0;
  for (int k = 0; k < 4; ++k)
    refined += integrate(pdf, quarter[k], quarter_points[k], 0.5 * tolerance, depth - 1);
  return refined;
}

double cell_probability(const DirectionPdf& pdf, int i, int j) {
  const double dt = kPi / kThetaCells / kStart, dp = 2 * kPi / kPhiCells / kStart;
  double sum = 0;
  for (int a = 0; a < kStart; ++a)
    for (int b = 0; b < kStart; ++b) {
      const double t0 = (i * kStart + a) * dt, p0 = (j * kStart + b) * dp;
      const Rect piece{t0, t0 + dt, p0, p0 + dp};
      sum += integrate(pdf, piece, points(pdf, piece), kAbsoluteTolerance / (kStart * kStart), kDepth);
    }
  return sum;
}

}  // namespace

ChiSquareResult sphere_chi_square(const DirectionSampler& sample, const DirectionPdf& pdf, int samples,
                                  uint64_t seed) {
  constexpr int kCells = kThetaCells * kPhiCells;
  std::vector<double> observed(kCells + 1, 0.0), expected(kCells + 1, 0.0);
  Rng rng(seed, 0);
  for (int n = 0; n < samples; ++n) {
    const std::optional<Vec3> w = sample(rng);
    observed[w && finite(*w) ? cell_of(*w) : kCells] += 1;
  }
  double total = 0;
  for (int i = 0; i < kThetaCells; ++i)
    for (int j = 0; j < kPhiCells; ++j) {
      const double p = cell_probability(pdf, i, j);
      expected[i * kPhiCells + j] = p * samples;
      total += p;
    }
  expected[kCells] = std::max(0.0, 1.0 - total) * samples;
  return chi_square_test(observed, expected);
}

}  // namespace lp::test

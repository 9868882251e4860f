#include "engine/sun/cone_pixels.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

Direction pixel_centre_direction(int x, int y, int width, int height) {
  const double theta = kPi * (y + 0.5) / height, phi = 2 * kPi * (x + 0.5) / width;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double angle_between(const Direction& a, const Direction& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return 2 * std::asin(std::min(1.0, 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz)));
}

std::vector<RowSpan> cone_row_spans(int width, int height, const Direction& axis, double radius) {
  const double theta = std::acos(std::clamp(axis[2], -1.0, 1.0));
  double phi = std::atan2(axis[1], axis[0]);
  if (phi < 0) phi += 2 * kPi;
  // Pixel centres lie at theta = pi (y + 0.5) / H and phi = 2 pi (x + 0.5) / W.
  const int y0 = std::max(0, int(std::floor(height * (theta - radius) / kPi - 0.5)));
  const int y1 = std::min(height - 1, int(std::ceil(height * (theta + radius) / kPi - 0.5)));
  const bool holds_pole = theta <= radius || kPi - theta <= radius;
  // Within the cone, longitude differs from the axis's by at most asin(sin radius / sin theta).
  const double half = holds_pole ? kPi : std::asin(std::min(1.0, std::sin(radius) / std::sin(theta)));
  const int x0 = int(std::floor(width * (phi - half) / (2 * kPi) - 0.5));
  const int x1 = int(std::ceil(width * (phi + half) / (2 * kPi) - 0.5));
  const int count = std::min(width, x1 - x0 + 1);
  const int first = holds_pole || count == width ? 0 : ((x0 % width) + width) % width;
  std::vector<RowSpan> spans;
  for (int y = y0; y <= y1; ++y) spans.push_back({y, first, count});
  return spans;
}

}  // namespace lp

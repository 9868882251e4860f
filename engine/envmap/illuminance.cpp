#include "engine/envmap/illuminance.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

double pixel_projected_solid_angle(int y, int width, int height) {
  const double t0 = kPi * y / height, t1 = std::min(kPi * (y + 1) / height, kPi / 2);
  if (!(t0 < t1)) return 0;
  // cos^2 t0 - cos^2 t1 = sin(t1 - t0) sin(t1 + t0), without cancellation in thin rows.
  return (kPi / width) * std::sin(t1 - t0) * std::sin(t1 + t0);
}

double upper_hemisphere_illuminance(const Image& image) {
  const int w = image.width(), h = image.height();
  double total = 0;
  for (int y = 0; y < h; ++y) {
    const double weight = pixel_projected_solid_angle(y, w, h);
    if (weight == 0) break;
    const float* row = image.row(y);
    double r = 0, g = 0, b = 0;
    for (int x = 0; x < w; ++x) r += row[3 * x], g += row[3 * x + 1], b += row[3 * x + 2];
    total += weight * (kRec709Weights.r * r + kRec709Weights.g * g + kRec709Weights.b * b);
  }
  return total;
}

double upper_hemisphere_illuminance(const EnvMap& map) {
  return *map.derived<double>("illuminance", [&] {
    return std::make_shared<const double>(upper_hemisphere_illuminance(map.image()));
  });
}

}  // namespace lp

#include "engine/mediancut/moment_tables.hpp"

#include <vector>

#include "engine/envmap/latlong.hpp"

namespace lp {
namespace {

std::vector<double> row_solid_angles(int width, int height) {
  std::vector<double> omega(height);
  for (int y = 0; y < height; ++y) omega[y] = latlong::pixel_solid_angle(y, width, height);
  return omega;
}

// A table of weight(x, y) * f(x + 0.5, y + 0.5).
template <class F>
SummedAreaTable weighted_table(const Image& image, LuminanceMode mode, const std::vector<double>& omega, F f) {
  const int w = image.width();
  return SummedAreaTable(w, image.height(), [&](int y, double* out) {
    const float* row = image.row(y);
    const double cy = y + 0.5;
    for (int x = 0; x < w; ++x) {
      const double weight = double(luminance({row[3 * x], row[3 * x + 1], row[3 * x + 2]}, mode)) * omega[y];
      out[x] = weight * f(x + 0.5, cy);
    }
  });
}

}  // namespace

SummedAreaTable build_weight_table(const Image& image, LuminanceMode mode) {
  const auto omega = row_solid_angles(image.width(), image.height());
  return weighted_table(image, mode, omega, [](double, double) { return 1.0; });
}

MomentTables build_moment_tables(const Image& image, LuminanceMode mode) {
  const auto omega = row_solid_angles(image.width(), image.height());
  return MomentTables{
      weighted_table(image, mode, omega, [](double x, double) { return x; }),
      weighted_table(image, mode, omega, [](double, double y) { return y; }),
      weighted_table(image, mode, omega, [](double x, double) { return x * x; }),
      weighted_table(image, mode, omega, [](double, double y) { return y * y; }),
  };
}

}  // namespace lp

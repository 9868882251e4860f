#include "engine/envmap/latlong_resample.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "engine/core/constants.hpp"
#include "engine/envmap/envmap.hpp"

namespace lp {
namespace {

// The source cells an output cell covers and their weights (summing to 1). Cell i of n spans
// [i / n, (i + 1) / n] of the axis; `measure` maps a position on the axis to the accumulated measure
// (solid angle up to a constant), so a piece's weight is the measure it spans.
struct Span {
  int first = 0;
  std::vector<double> weights;
};

std::vector<Span> spans(int source_count, int count, const std::function<double(double)>& measure) {
  std::vector<Span> out(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double a = double(i) / count, b = double(i + 1) / count;
    const int first = std::clamp(int(std::floor(a * source_count)), 0, source_count - 1);
    const int last = std::clamp(int(std::ceil(b * source_count)) - 1, first, source_count - 1);
    Span& s = out[size_t(i)];
    s.first = first;
    double total = 0;
    for (int j = first; j <= last; ++j) {
      const double lo = std::max(a, double(j) / source_count), hi = std::min(b, double(j + 1) / source_count);
      const double w = hi > lo ? measure(hi) - measure(lo) : 0.0;
      s.weights.push_back(w);
      total += w;
    }
    for (double& w : s.weights) w = total > 0 ? w / total : 1.0 / double(s.weights.size());
  }
  return out;
}

// Every row of the map on `width` columns.
Image resample_columns(const Image& image, int width) {
  const auto columns = spans(image.width(), width, [](double u) { return u; });
  Image out(width, image.height());
  tbb::parallel_for(0, image.height(), [&](int y) {
    const float* in = image.row(y);
    float* row = out.row(y);
    for (int x = 0; x < width; ++x) {
      const Span& s = columns[size_t(x)];
      double r = 0, g = 0, b = 0;
      for (size_t k = 0; k < s.weights.size(); ++k) {
        const float* p = in + 3 * (size_t(s.first) + k);
        r += s.weights[k] * p[0], g += s.weights[k] * p[1], b += s.weights[k] * p[2];
      }
      row[3 * x] = float(r), row[3 * x + 1] = float(g), row[3 * x + 2] = float(b);
    }
  });
  return out;
}

Image resample_rows(const Image& image, int height) {
  // Solid angle from the pole down to v, up to a constant: 1 - cos(pi v).
  const auto rows = spans(image.height(), height, [](double v) { return 1.0 - std::cos(kPi * v); });
  const int width = image.width();
  Image out(width, height);
  tbb::parallel_for(0, height, [&](int y) {
    const Span& s = rows[size_t(y)];
    std::vector<double> sum(size_t(width) * 3, 0.0);
    for (size_t k = 0; k < s.weights.size(); ++k) {
      const float* in = image.row(s.first + int(k));
      for (size_t i = 0; i < sum.size(); ++i) sum[i] += s.weights[k] * in[i];
    }
    float* row = out.row(y);
    for (size_t i = 0; i < sum.size(); ++i) row[i] = float(sum[i]);
  });
  return out;
}

}  // namespace

Image resample_latlong(const Image& image, int width, int height) {
  if (width == image.width() && height == image.height()) return image;
  return resample_rows(resample_columns(image, width), height);
}

int64_t resample_latlong_bytes(int source_height, int width, int height) {
  return EnvMap::image_bytes(width, source_height) + EnvMap::image_bytes(width, height);
}

}  // namespace lp

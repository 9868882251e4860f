#include "engine/sampling/piecewise_constant_2d.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"

namespace lp {
namespace {

// Index i with cdf[i] <= u < cdf[i + 1], skipping zero-width cells; cdf has n + 1 entries, 0 .. 1.
int find_interval(const float* cdf, int n, float u) {
  const float* it = std::upper_bound(cdf + 1, cdf + n + 1, u);
  return std::clamp(int(it - cdf) - 1, 0, n - 1);
}

// Prefix sums of `w` (n values) into cdf (n + 1 values), normalised; returns the sum.
// A row of zeros gets a uniform CDF so that it is well formed (it is never selected).
double build_cdf(const float* w, int n, float* cdf) {
  double sum = 0;
  cdf[0] = 0;
  for (int i = 0; i < n; ++i) {
    sum += w[i];
    cdf[i + 1] = float(sum);
  }
  if (sum > 0) {
    const double inv = 1.0 / sum;  // over a float's range when the weights are tiny
    for (int i = 1; i < n; ++i) cdf[i] = float(cdf[i] * inv);
  } else {
    for (int i = 1; i < n; ++i) cdf[i] = float(i) / float(n);
  }
  cdf[n] = 1.0f;
  return sum;
}

}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(int width, int height, const RowFiller& fill_row)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw Error(ErrorKind::InvalidArgument, "distribution grid must not be empty");
  const size_t cells = size_t(width) * size_t(height);
  row_sums_.resize(size_t(height));
  weight_.reset(new float[cells]);
  conditional_cdf_.reset(new float[size_t(height) * size_t(width + 1)]);
  tbb::parallel_for(0, height, [&](int y) {
    float* row = &weight_[size_t(y) * width];
    fill_row(y, row);
    row_sums_[size_t(y)] = build_cdf(row, width, &conditional_cdf_[size_t(y) * (width + 1)]);
  });
  for (double s : row_sums_) total_ += s;
  if (!(total_ > 0)) throw Error(ErrorKind::InvalidData, "the map has no energy to sample (every weight is zero)");

  std::vector<float> row_weights(row_sums_.begin(), row_sums_.end());
  marginal_cdf_.resize(size_t(height) + 1);
  build_cdf(row_weights.data(), height, marginal_cdf_.data());

  // Density on the unit square = weight / mean weight (applied on lookup: no pass over the table).
  density_scale_ = double(width) * double(height) / total_;
}

GridSample PiecewiseConstant2D::sample(float u1, float u2) const {
  GridSample s;
  s.y = find_interval(marginal_cdf_.data(), height_, u2);
  const float* row_cdf = conditional_cdf(s.y);
  s.x = find_interval(row_cdf, width_, u1);
  // Offsets within the cell, by linear inversion of the CDF inside it.
  const double dv = (double(u2) - marginal_cdf_[s.y]) / (double(marginal_cdf_[s.y + 1]) - marginal_cdf_[s.y]);
  const double du = (double(u1) - row_cdf[s.x]) / (double(row_cdf[s.x + 1]) - row_cdf[s.x]);
  s.u = (s.x + std::clamp(du, 0.0, double(kOneMinusEpsilon))) / width_;
  s.v = (s.y + std::clamp(dv, 0.0, double(kOneMinusEpsilon))) / height_;
  s.density = density(s.x, s.y);
  return s;
}

}  // namespace lp

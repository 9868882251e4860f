#include "engine/sampling/piecewise_constant_2d.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/sampling/cdf_1d.hpp"

namespace lp {

int64_t PiecewiseConstant2D::memory_bytes(int64_t width, int64_t height) {
  const int64_t row_guide = cdf_1d::guide_size(int(width), kColumnsPerGuide) + 1,
                marginal_guide = cdf_1d::guide_size(int(height), kRowsPerGuide) + 1;
  return height * int64_t(sizeof(double)) + (height + 1) * int64_t(sizeof(float)) +
         marginal_guide * int64_t(sizeof(uint32_t)) + height * (width + 1) * int64_t(sizeof(Cell)) +
         height * row_guide * int64_t(sizeof(uint32_t));
}

PiecewiseConstant2D::PiecewiseConstant2D(int width, int height, const RowFiller& fill_row)
    : width_(width),
      height_(height),
      row_guide_size_(cdf_1d::guide_size(width, kColumnsPerGuide)),
      marginal_guide_size_(cdf_1d::guide_size(height, kRowsPerGuide)) {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::InvalidArgument, "distribution grid must not be empty");
  row_sums_.resize(size_t(height));
  cells_.reset(new Cell[size_t(height) * size_t(width + 1)]);
  row_guides_.reset(new uint32_t[size_t(height) * size_t(row_guide_size_ + 1)]);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> weights(static_cast<size_t>(width));
    for (int y = rows.begin(); y != rows.end(); ++y) {
      fill_row(y, weights.data());
      Cell* cells = &cells_[size_t(y) * size_t(width + 1)];
      for (int x = 0; x < width; ++x) cells[x].weight = weights[size_t(x)];
      cells[width].weight = 0;
      row_sums_[size_t(y)] = cdf_1d::build(weights.data(), width, &cells[0].cdf, kCdfStride);
      cdf_1d::build_guide(&cells[0].cdf, kCdfStride, width, row_guide_size_,
                          &row_guides_[size_t(y) * size_t(row_guide_size_ + 1)]);
    }
  });
  for (double s : row_sums_) total_ += s;
  if (!(total_ > 0))
    throw Error(ErrorKind::InvalidData, "the map has no energy to sample (every weight is zero)");

  marginal_cdf_.resize(size_t(height) + 1);
  cdf_1d::build(row_sums_.data(), height, marginal_cdf_.data());
  marginal_guide_.resize(size_t(marginal_guide_size_) + 1);
  cdf_1d::build_guide(marginal_cdf_.data(), 1, height, marginal_guide_size_, marginal_guide_.data());

  // Density on the unit square = weight / mean weight (applied on lookup: no pass over the table).
  density_scale_ = double(width) * double(height) / total_;
}

GridSample PiecewiseConstant2D::sample(float u1, float u2) const {
  GridSample s;
  s.y = cdf_1d::find(marginal_cdf_.data(), 1, height_, marginal_guide_.data(), marginal_guide_size_, u2);
  const Cell* cells = row(s.y);
  s.x = cdf_1d::find(&cells[0].cdf, kCdfStride, width_, row_guide(s.y), row_guide_size_, u1);
  // Offsets within the cell, by linear inversion of the CDF inside it.
  const double dv = (double(u2) - marginal_cdf_[s.y]) / (double(marginal_cdf_[s.y + 1]) - marginal_cdf_[s.y]);
  const double du = (double(u1) - cells[s.x].cdf) / (double(cells[s.x + 1].cdf) - cells[s.x].cdf);
  s.u = (s.x + std::clamp(du, 0.0, double(kOneMinusEpsilon))) / width_;
  s.v = (s.y + std::clamp(dv, 0.0, double(kOneMinusEpsilon))) / height_;
  s.density = float(double(cells[s.x].weight) * density_scale_);
  return s;
}

}  // namespace lp

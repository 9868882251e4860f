#pragma once
// A piecewise-constant density over the unit square on a W x H grid of non-negative weights:
// a marginal distribution over rows and a conditional distribution over the columns of each row,
// sampled by inverting the CDFs (monotone, so stratified and low-discrepancy points stay so).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace lp {

struct GridSample {
  int x = 0, y = 0;        // the cell
  double u = 0, v = 0;     // continuous position in [0, 1)^2 (u across columns, v down rows)
  float density = 0;       // density on the unit square: weight / mean weight
};

class PiecewiseConstant2D {
 public:
  // `fill_row(y, out)` writes the width non-negative weights of row y; rows are filled in parallel,
  // each one straight into the weight table and turned into its CDF while still in cache.
  // Throws lp::Error(InvalidData) if every weight is zero.
  using RowFiller = std::function<void(int y, float* out)>;
  PiecewiseConstant2D(int width, int height, const RowFiller& fill_row);

  // The bytes a distribution over width x height cells holds.
  static int64_t memory_bytes(int64_t width, int64_t height) {
    return height * (int64_t(sizeof(double)) + 2 * int64_t(sizeof(float))) +
           int64_t(sizeof(float)) * (2 * width + 1) * height;
  }

  int width() const { return width_; }
  int height() const { return height_; }

  // u1 picks the column within the row, u2 picks the row. Both in [0, 1).
  GridSample sample(float u1, float u2) const;
  float density(int x, int y) const {
    return float(double(weight_[size_t(y) * width_ + x]) * density_scale_);
  }

  // Row probabilities (sum 1) and the marginal CDF (height + 1 entries, 0 .. 1).
  std::span<const float> marginal_cdf() const { return marginal_cdf_; }
  double row_probability(int y) const { return double(marginal_cdf_[y + 1]) - marginal_cdf_[y]; }
  std::span<const double> row_weight_sums() const { return row_sums_; }
  double total_weight() const { return total_; }

 private:
  const float* conditional_cdf(int y) const { return &conditional_cdf_[size_t(y) * (width_ + 1)]; }

  int width_, height_;
  double total_ = 0;
  std::vector<double> row_sums_;
  std::vector<float> marginal_cdf_;     // height + 1
  // Large tables are left uninitialised on allocation (every entry is written once).
  std::unique_ptr<float[]> conditional_cdf_;  // height * (width + 1)
  std::unique_ptr<float[]> weight_;           // width * height
  // weight -> density on the unit square; double because tiny weights make it overflow a float
  double density_scale_ = 0;
};

}  // namespace lp

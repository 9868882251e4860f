#pragma once
// A piecewise-constant density over the unit square on a W x H grid of non-negative weights:
// a marginal distribution over rows and a conditional distribution over the columns of each row,
// sampled by inverting the CDFs (monotone, so stratified and low-discrepancy points stay so).
// The inversions go through guide tables (see cdf_1d.hpp), and each cell's CDF entry sits beside
// its weight, so that a sample touches few cache lines.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace lp {

struct GridSample {
  int x = 0, y = 0;     // the cell
  double u = 0, v = 0;  // continuous position in [0, 1)^2 (u across columns, v down rows)
  float density = 0;    // density on the unit square: weight / mean weight
};

class PiecewiseConstant2D {
 public:
  // `fill_row(y, out)` writes the width non-negative weights of row y; rows are filled in parallel,
  // each one turned into its CDF and guide table while still in cache.
  // Throws lp::Error(InvalidData) if every weight is zero.
  using RowFiller = std::function<void(int y, float* out)>;
  PiecewiseConstant2D(int width, int height, const RowFiller& fill_row);

  // The bytes a distribution over width x height cells holds.
  static int64_t memory_bytes(int64_t width, int64_t height);

  int width() const { return width_; }
  int height() const { return height_; }

  // u1 picks the column within the row, u2 picks the row. Both in [0, 1).
  GridSample sample(float u1, float u2) const;
  float density(int x, int y) const { return float(double(cell(x, y).weight) * density_scale_); }
  // Starts loading what density(x, y) reads, for a caller that knows the cell ahead of its use.
  void prefetch(int x, int y) const { __builtin_prefetch(&cell(x, y)); }

  // The marginal CDF over rows (height + 1 entries, 0 .. 1): the one sample() inverts.
  std::span<const float> marginal_cdf() const { return marginal_cdf_; }
  // The sum of each row's weights, and of all of them.
  std::span<const double> row_weight_sums() const { return row_sums_; }
  double total_weight() const { return total_; }

 private:
  struct Cell {
    float cdf;     // the row's CDF at the cell's left edge (width + 1 per row, the last is 1)
    float weight;  // 0 in the last
  };
  static constexpr size_t kCdfStride = sizeof(Cell) / sizeof(float);
  static constexpr int kColumnsPerGuide = 4, kRowsPerGuide = 2;

  const Cell* row(int y) const { return &cells_[size_t(y) * size_t(width_ + 1)]; }
  const Cell& cell(int x, int y) const { return row(y)[x]; }
  const uint32_t* row_guide(int y) const { return &row_guides_[size_t(y) * size_t(row_guide_size_ + 1)]; }

  int width_, height_, row_guide_size_, marginal_guide_size_;
  double total_ = 0;
  std::vector<double> row_sums_;
  std::vector<float> marginal_cdf_;       // height + 1
  std::vector<uint32_t> marginal_guide_;  // marginal_guide_size_ + 1
  // Large tables are left uninitialised on allocation (every entry is written once).
  std::unique_ptr<Cell[]> cells_;           // height * (width + 1)
  std::unique_ptr<uint32_t[]> row_guides_;  // height * (row_guide_size_ + 1)
  // weight -> density on the unit square; double because tiny weights make it overflow a float
  double density_scale_ = 0;
};

}  // namespace lp

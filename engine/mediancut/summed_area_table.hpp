#pragma once
// A summed-area table in double precision: S(x, y) = sum of the values in [0, x) x [0, y), so any
// rectangle's sum is four lookups. Double because an 8k x 4k map's totals overwhelm a float's 24 bits.
//
// Stored as horizontal strips, each an independent table of its own rows, plus one offset row per
// strip (the full table's row at the strip's top): S(x, y) = local(x, y) + offset(strip of y, x).
// That lets every strip be built in parallel in a single pass over memory (each row adds the row
// above while it is still in cache), instead of a row pass and then a column pass over the whole
// table: at 8192 x 4096 the table is 268 MB, and the second pass cost as much as the first.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <vector>

namespace lp {

class SummedAreaTable {
 public:
  // fill_row(y, out) writes the `width` values of row y to out[0 .. width). Rows are filled in
  // parallel (oneTBB), so fill_row must be safe to call concurrently for different rows.
  using RowFill = std::function<void(int y, double* out)>;
  SummedAreaTable(int width, int height, const RowFill& fill_row);

  int width() const { return width_; }
  int height() const { return height_; }

  // Sum over [0, x) x [0, y); 0 <= x <= width, 0 <= y <= height.
  double at(int x, int y) const { return table_[size_t(y) * stride_ + size_t(x)] + row_offset_[y][x]; }
  // Sum over the half-open rectangle [x0, x1) x [y0, y1).
  double sum(int x0, int y0, int x1, int y1) const { return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0); }
  double total() const { return at(width_, height_); }

  size_t memory_bytes() const { return (size_t(height_ + 1) + offsets_.size() / stride_) * stride_ * sizeof(double); }

  // The bytes a table over width x height values holds (memory_bytes() of the built table).
  static int64_t memory_bytes(int64_t width, int64_t height);
 private:
  struct Free {
    void operator()(double* p) const { std::free(p); }
  };

  int width_, height_;
  size_t stride_;                           // width + 1
  std::unique_ptr<double[], Free> table_;   // (height + 1) x (width + 1): each strip's local table
  std::vector<double> offsets_;             // one row of width + 1 per strip
  std::vector<const double*> row_offset_;   // per table row, its strip's offset row
};

}  // namespace lp

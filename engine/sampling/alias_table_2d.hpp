#pragma once
// O(1) sampling of the cells of a piecewise-constant 2D density (Walker/Vose alias method), two
// levels: an alias table over rows, then one per row over its columns. Not monotone: use it for
// independent random samples, the inverse CDF for stratified and low-discrepancy ones.
// The table holds only the choices (8 bytes a cell); a sample's density is read from the distribution
// it was built from, which keeps every cell's weight already.
#include <cstdint>
#include <vector>

#include "engine/sampling/piecewise_constant_2d.hpp"

namespace lp {

class AliasTable2D {
 public:
  explicit AliasTable2D(const PiecewiseConstant2D& dist);
  // The bytes a table over width x height cells holds.
  static int64_t memory_bytes(int64_t width, int64_t height) {
    return height * int64_t(sizeof(Entry)) + width * height * int64_t(sizeof(Entry));
  }

  struct Cell {
    int x = 0, y = 0;
  };
  // The cell chosen by r_row and r_col, independent uniform 64-bit integers.
  Cell pick(uint64_t r_row, uint64_t r_col) const;
  // The sample at offsets (fu, fv) within the cell, with its density in `dist` (the distribution the
  // table was built from).
  GridSample at(const PiecewiseConstant2D& dist, Cell c, float fu, float fv) const;
  GridSample sample(const PiecewiseConstant2D& dist, uint64_t r_row, uint64_t r_col, float fu,
                    float fv) const {
    return at(dist, pick(r_row, r_col), fu, fv);
  }
  // The column entry pick() will read for these bits (to prefetch it in batches).
  const void* column_entry_address(uint64_t r_row, uint64_t r_col) const;

 private:
  struct Entry {
    float threshold;  // keep this index if the uniform is below it, else take `alias`
    uint32_t alias;
  };
  static void build(const double* weights, int n, Entry* out);
  static bool keep(const Entry& e, uint64_t r);
  static uint32_t slot(int n, uint64_t r) { return uint32_t(((r >> 32) * uint64_t(n)) >> 32); }
  uint32_t row(uint64_t r_row) const;

  int width_, height_;
  std::vector<Entry> rows_;     // height
  std::vector<Entry> columns_;  // height * width
};

}  // namespace lp

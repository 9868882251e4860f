#pragma once
// O(1) sampling of the cells of a piecewise-constant 2D density (Walker/Vose alias method), two
// levels: an alias table over rows, then one per row over its columns. Not monotone: use it for
// independent random samples, the inverse CDF for stratified and low-discrepancy ones.
#include <cstdint>
#include <vector>

#include "engine/sampling/piecewise_constant_2d.hpp"

namespace lp {

class AliasTable2D {
 public:
  explicit AliasTable2D(const PiecewiseConstant2D& dist);
  // The bytes a table over width x height cells holds.
  static int64_t memory_bytes(int64_t width, int64_t height) {
    return height * int64_t(sizeof(Entry)) + width * height * int64_t(sizeof(ColumnEntry));
  }

  // r_row and r_col are independent uniform 64-bit integers; (fu, fv) the offsets within the cell.
  GridSample sample(uint64_t r_row, uint64_t r_col, float fu, float fv) const;
  // The column entry sample() will read for these bits (to prefetch it in batches).
  const void* column_entry_address(uint64_t r_row, uint64_t r_col) const;

 private:
  struct Entry {
    float threshold;  // keep this index if the uniform is below it, else take `alias`
    uint32_t alias;
  };
  // Column entries carry both candidates' densities, so a sample touches one 16-byte entry.
  struct ColumnEntry {
    Entry entry;
    float density_self, density_alias;
  };
  static void build(const double* weights, int n, Entry* out);
  static bool keep(const Entry& e, uint64_t r);
  static uint32_t slot(int n, uint64_t r) { return uint32_t(((r >> 32) * uint64_t(n)) >> 32); }

  int width_, height_;
  std::vector<Entry> rows_;           // height
  std::vector<ColumnEntry> columns_;  // height * width
};

}  // namespace lp

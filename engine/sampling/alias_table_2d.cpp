#include "engine/sampling/alias_table_2d.hpp"

#include <tbb/parallel_for.h>

namespace lp {

// Vose's alias method: every slot holds its own probability mass up to `threshold` and the rest
// from one `alias`; sampling is one slot pick and one comparison.
void AliasTable2D::build(const double* weights, int n, Entry* out) {
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += weights[i];
  std::vector<double> scaled(static_cast<size_t>(n));
  std::vector<uint32_t> small, large;
  small.reserve(size_t(n));
  large.reserve(size_t(n));
  for (int i = 0; i < n; ++i) {
    scaled[size_t(i)] = sum > 0 ? weights[i] * n / sum : 1.0;
    (scaled[size_t(i)] < 1.0 ? small : large).push_back(uint32_t(i));
  }
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back(), l = large.back();
    small.pop_back();
    out[s] = {float(scaled[s]), l};
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  for (uint32_t i : large) out[i] = {1.0f, i};
  for (uint32_t i : small) out[i] = {1.0f, i};  // only rounding leftovers
}

AliasTable2D::AliasTable2D(const PiecewiseConstant2D& dist) : width_(dist.width()), height_(dist.height()) {
  rows_.resize(size_t(height_));
  build(dist.row_weight_sums().data(), height_, rows_.data());
  columns_.resize(size_t(height_) * size_t(width_));
  tbb::parallel_for(0, height_, [&](int y) {
    std::vector<double> w(static_cast<size_t>(width_));
    for (int x = 0; x < width_; ++x) w[size_t(x)] = dist.density(x, y);
    build(w.data(), width_, &columns_[size_t(y) * width_]);
  });
}

// The high 32 bits pick the slot (multiply-shift), the low 24 bits are the coin for the threshold.
bool AliasTable2D::keep(const Entry& e, uint64_t r) {
  return float(r & 0xffffff) * 0x1p-24f < e.threshold;
}

uint32_t AliasTable2D::row(uint64_t r_row) const {
  const uint32_t row_slot = slot(height_, r_row);
  return keep(rows_[row_slot], r_row) ? row_slot : rows_[row_slot].alias;
}

const void* AliasTable2D::column_entry_address(uint64_t r_row, uint64_t r_col) const {
  return &columns_[size_t(row(r_row)) * width_ + slot(width_, r_col)];
}

AliasTable2D::Cell AliasTable2D::pick(uint64_t r_row, uint64_t r_col) const {
  Cell c;
  c.y = int(row(r_row));
  const uint32_t col_slot = slot(width_, r_col);
  const Entry& e = columns_[size_t(c.y) * width_ + col_slot];
  c.x = int(keep(e, r_col) ? col_slot : e.alias);
  return c;
}

GridSample AliasTable2D::at(const PiecewiseConstant2D& dist, Cell c, float fu, float fv) const {
  GridSample s;
  s.x = c.x;
  s.y = c.y;
  s.density = dist.density(c.x, c.y);
  s.u = (s.x + double(fu)) / width_;
  s.v = (s.y + double(fv)) / height_;
  return s;
}

}  // namespace lp

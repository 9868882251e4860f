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

AliasTable2D::AliasTable2D(const PiecewiseConstant2D& dist)
    : dist_(dist), width_(dist.width()), height_(dist.height()) {
  rows_.resize(size_t(height_));
  build(dist.row_weight_sums().data(), height_, rows_.data());
  columns_.resize(size_t(height_) * size_t(width_));
  tbb::parallel_for(0, height_, [&](int y) {
    std::vector<double> w(static_cast<size_t>(width_));
    for (int x = 0; x < width_; ++x) w[size_t(x)] = dist.density(x, y);
    build(w.data(), width_, &columns_[size_t(y) * width_]);
  });
}

// The high 32 bits pick the slot (multiply-shift, no modulo bias worth speaking of); the low 24
// bits are the coin for the threshold.
uint32_t AliasTable2D::pick(const Entry* table, int n, uint64_t r) {
  const auto slot = uint32_t(((r >> 32) * uint64_t(n)) >> 32);
  const float coin = float(r & 0xffffff) * 0x1p-24f;
  const Entry& e = table[slot];
  return coin < e.threshold ? slot : e.alias;
}

GridSample AliasTable2D::sample(uint64_t r_row, uint64_t r_col, float fu, float fv) const {
  GridSample s;
  s.y = int(pick(rows_.data(), height_, r_row));
  s.x = int(pick(&columns_[size_t(s.y) * width_], width_, r_col));
  s.u = (s.x + double(fu)) / width_;
  s.v = (s.y + double(fv)) / height_;
  s.density = dist_.density(s.x, s.y);
  return s;
}

}  // namespace lp

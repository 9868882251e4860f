#pragma once
// Normalised CDFs of piecewise-constant 1D weights, and their inversion through a guide table
// (Chen & Asau 1974): guide[j] is the cell holding u = j / g, so finding the cell of u is one table
// lookup and a search over the few cells between two guides instead of over the whole CDF.
// CDFs are read with a stride (in floats) so that they can sit interleaved with per-cell data.
#include <cstddef>
#include <cstdint>

namespace lp::cdf_1d {

// Prefix sums of the n weights `w` into cdf[i * stride] for i = 0 .. n, normalised to 0 .. 1;
// returns the sum. All-zero weights get a uniform CDF, so that it is well formed.
template <class Weight>
double build(const Weight* w, int n, float* cdf, size_t stride = 1) {
  double sum = 0;
  cdf[0] = 0;
  for (int i = 0; i < n; ++i) {
    sum += double(w[i]);
    cdf[size_t(i + 1) * stride] = float(sum);
  }
  if (sum > 0) {
    const double inv = 1.0 / sum;  // over a float's range when the weights are tiny
    for (int i = 1; i < n; ++i) cdf[size_t(i) * stride] = float(cdf[size_t(i) * stride] * inv);
  } else {
    for (int i = 1; i < n; ++i) cdf[size_t(i) * stride] = float(i) / float(n);
  }
  cdf[size_t(n) * stride] = 1.0f;
  // Trailing empty cells end at 1 too, which the rounded normalisation may fall short of.
  for (int i = n - 1; i > 0 && sum > 0 && !(w[i] > 0); --i) cdf[size_t(i) * stride] = 1.0f;
  return sum;
}

// The number of guide intervals for a CDF over n cells (the table holds one more entry).
inline int guide_size(int n, int cells_per_guide) {
  return n / cells_per_guide > 1 ? n / cells_per_guide : 1;
}

// guide[j] = the cell holding j / g, for j = 0 .. g (up to rounding, which find() corrects).
void build_guide(const float* cdf, size_t stride, int n, int g, uint32_t* guide);

// The cell i < n with cdf[i] <= u < cdf[i + 1], skipping zero-width cells (the largest i with
// cdf[i] <= u): the same answer as a binary search over the whole CDF, for every float u in [0, 1).
int find(const float* cdf, size_t stride, int n, const uint32_t* guide, int g, float u);

}  // namespace lp::cdf_1d

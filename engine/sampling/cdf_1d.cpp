#include "engine/sampling/cdf_1d.hpp"

#include <algorithm>

namespace lp::cdf_1d {

// Each cell takes the guides up to its right edge: guide j belongs to cell i while j <= cdf[i + 1] * g
// (a guide exactly on an edge goes to the cell left of it, and the product is rounded: find() corrects
// both). One pass over the cells without unpredictable branches: every cell writes the next guide,
// which its owner writes last, and only a cell holding several guides loops. guide[g] is the last cell.
void build_guide(const float* cdf, size_t stride, int n, int g, uint32_t* guide) {
  int j = 0;
  for (int i = 0; i < n - 1; ++i) {
    const int end = std::min(g, int(cdf[size_t(i + 1) * stride] * float(g)) + 1);
    guide[j] = uint32_t(i);
    for (int k = j + 1; k < end; ++k) guide[k] = uint32_t(i);
    j = std::max(j, end);
  }
  for (; j <= g; ++j) guide[j] = uint32_t(n - 1);
}

int find(const float* cdf, size_t stride, int n, const uint32_t* guide, int g, float u) {
  const int j = std::clamp(int(u * float(g)), 0, g - 1);
  int lo = int(guide[j]), hi = int(guide[j + 1]);  // the answer, unless u * g rounded across j
  // A u drawn uniformly meets n / g + 1 cells between its guides on average, whatever the weights.
  // Counting the few at or below u has no branch to mispredict, and its loads do not wait on each
  // other as a binary search's do; a long run of cells (empty ones) is still searched.
  constexpr int kCountedCells = 8;
  if (hi - lo <= kCountedCells) {
    int below = 0;
    for (int i = lo + 1; i <= hi; ++i) below += cdf[size_t(i) * stride] <= u;
    lo += below;
    hi = lo;
  }
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (cdf[size_t(mid) * stride] <= u)
      lo = mid;
    else
      hi = mid - 1;
  }
  // u * g and j / g are rounded: u within an ulp of a guide's value may belong to a neighbouring cell.
  while (lo + 1 < n && cdf[size_t(lo + 1) * stride] <= u) ++lo;
  while (lo > 0 && cdf[size_t(lo) * stride] > u) --lo;
  return lo;
}

}  // namespace lp::cdf_1d

#include "engine/sampling/cdf_1d.hpp"

#include <algorithm>

namespace lp::cdf_1d {

void build_guide(const float* cdf, size_t stride, int n, int g, uint32_t* guide) {
  int i = 0;
  for (int j = 0; j <= g; ++j) {
    const float u = float(j) / float(g);
    while (i < n - 1 && cdf[size_t(i + 1) * stride] <= u) ++i;
    guide[j] = uint32_t(i);
  }
}

int find(const float* cdf, size_t stride, int n, const uint32_t* guide, int g, float u) {
  const int j = std::clamp(int(u * float(g)), 0, g - 1);
  int lo = int(guide[j]), hi = int(guide[j + 1]);  // the answer, unless u * g rounded across j
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

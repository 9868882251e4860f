#include "engine/sun/sun_search.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <vector>

namespace lp {
namespace {

struct Best {
  double value = -1;
  int64_t index = 0;  // row-major position, the tie-break
  Best better(const Best& o) const {
    return o.value > value || (o.value == value && o.index < index) ? o : *this;
  }
};

// The energy of the window of `k` columns from x0 (wrapping past the last column) and rows [y0, y1).
double window_energy(const SummedAreaTable& t, int x0, int k, int y0, int y1) {
  const int w = t.width();
  if (k >= w) return t.sum(0, y0, w, y1);
  if (x0 + k <= w) return t.sum(x0, y0, x0 + k, y1);
  return t.sum(x0, y0, w, y1) + t.sum(0, y0, x0 + k - w, y1);
}

// The window origins along one axis: every `step` from 0, and the last one that fits.
std::vector<int> row_origins(int height, int k, int step) {
  std::vector<int> out;
  const int last = std::max(0, height - k);
  for (int y = 0; y < last; y += step) out.push_back(y);
  out.push_back(last);
  return out;
}

}  // namespace

PixelPos brightest_spot(const Image& image, const SummedAreaTable& weight, LuminanceMode mode, int window) {
  const int w = image.width(), h = image.height();
  const int k = std::max(1, window), step = std::max(1, k / 2);
  const std::vector<int> rows = row_origins(h, k, step);
  const Best spot = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, rows.size()), Best{},
      [&](const tbb::blocked_range<size_t>& r, Best best) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          const int y0 = rows[i], y1 = std::min(h, y0 + k);
          for (int x0 = 0; x0 < w; x0 += step)
            best = best.better({window_energy(weight, x0, k, y0, y1), int64_t(y0) * w + x0});
        }
        return best;
      },
      [](const Best& a, const Best& b) { return a.better(b); });

  // The brightest pixel of the window and the half window around it.
  const int wx = int(spot.index % w), wy = int(spot.index / w);
  Best peak;
  for (int y = std::max(0, wy - step); y < std::min(h, wy + k + step); ++y)
    for (int i = -step; i < k + step && i < w; ++i) {
      const int x = ((wx + i) % w + w) % w;
      peak = peak.better({double(luminance(image.at(x, y), mode)), int64_t(y) * w + x});
    }
  return {int(peak.index % w), int(peak.index / w)};
}

}  // namespace lp

#include "engine/sun/sun_search.hpp"

#include <algorithm>
#include <queue>

namespace lp {
namespace {

struct Candidate {
  float luminance = 0;
  int64_t index = 0;  // row-major position, the tie-break
};

// Brighter, or as bright and earlier: the order of the answer.
bool before(const Candidate& a, const Candidate& b) {
  return a.luminance > b.luminance || (a.luminance == b.luminance && a.index < b.index);
}

}  // namespace

std::vector<PixelPos> brightest_pixels(const Image& image, LuminanceMode mode, int count) {
  const int w = image.width(), h = image.height();
  // The heap's top is the weakest candidate kept.
  std::priority_queue<Candidate, std::vector<Candidate>, decltype(&before)> kept(&before);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Candidate c{luminance(image.at(x, y), mode), int64_t(y) * w + x};
      if (int(kept.size()) < count)
        kept.push(c);
      else if (before(c, kept.top())) {
        kept.pop();
        kept.push(c);
      }
    }
  std::vector<Candidate> sorted;
  for (; !kept.empty(); kept.pop()) sorted.push_back(kept.top());
  std::reverse(sorted.begin(), sorted.end());
  std::vector<PixelPos> out;
  for (const Candidate& c : sorted) out.push_back({int(c.index % w), int(c.index / w)});
  return out;
}

}  // namespace lp

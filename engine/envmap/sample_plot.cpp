#include "engine/envmap/sample_plot.hpp"

namespace lp {
namespace {

constexpr int kHalf = 2;  // 5x5 squares

// Calls f(x, y) for each pixel of the 5x5 square around (cx, cy): wraps across the phi seam, clips at the
// poles.
template <class F>
void for_each_in_square(int cx, int cy, int width, int height, F&& f) {
  for (int dy = -kHalf; dy <= kHalf; ++dy) {
    const int y = cy + dy;
    if (y < 0 || y >= height) continue;
    for (int dx = -kHalf; dx <= kHalf; ++dx) f((cx + dx + width) % width, y);
  }
}

}  // namespace

std::vector<uint8_t> plot_sample_marks(const EnvMap& map, std::span<const EnvSample> samples,
                                       const ToneMap& tone) {
  std::vector<uint8_t> rgb = tone_map_rgb8(map.image(), tone);
  const int w = map.width(), h = map.height();
  for (const EnvSample& s : samples)
    for_each_in_square(s.pixel_x, s.pixel_y, w, h, [&](int x, int y) {
      uint8_t* p = &rgb[(size_t(y) * w + x) * 3];
      p[0] = 0, p[1] = 0, p[2] = 255;
    });
  return rgb;
}

std::vector<uint8_t> plot_sample_windows(const EnvMap& map, std::span<const EnvSample> samples,
                                         const ToneMap& tone) {
  Image windows(map.width(), map.height());
  for (const EnvSample& s : samples)
    for_each_in_square(s.pixel_x, s.pixel_y, map.width(), map.height(),
                       [&](int x, int y) { windows.set(x, y, map.image().at(x, y)); });
  return tone_map_rgb8(windows, tone);
}

}  // namespace lp

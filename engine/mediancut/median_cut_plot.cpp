#include "engine/mediancut/median_cut_plot.hpp"

#include <algorithm>

namespace lp {
namespace {

// Calls f(x, y) for the square of half-size `half` around (cx, cy): wraps in phi, clips at the poles.
template <class F>
void for_each_in_square(int cx, int cy, int half, int width, int height, F&& f) {
  for (int y = std::max(0, cy - half); y <= std::min(height - 1, cy + half); ++y)
    for (int dx = -half; dx <= half; ++dx) f(((cx + dx) % width + width) % width, y);
}

void paint(std::vector<uint8_t>& rgb, int width, int x, int y, uint8_t r, uint8_t g, uint8_t b) {
  uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
  p[0] = r, p[1] = g, p[2] = b;
}

std::vector<uint8_t> plot_regions(const Image& map, const MedianCutResult& result, int half, const ToneMap& tone) {
  std::vector<uint8_t> rgb = tone_map_rgb8(map, tone);
  const int w = map.width(), h = map.height();
  // Each region draws only its top and left edges, and only inside the map: every cut is drawn once.
  for (const auto& light : result.lights) {
    const Region& r = light.region;
    if (r.y0 > 0)
      for (int x = r.x0; x < r.x1; ++x) paint(rgb, w, x, r.y0, 0, 255, 0);
    if (r.x0 > 0)
      for (int y = r.y0; y < r.y1; ++y) paint(rgb, w, r.x0, y, 0, 255, 0);
  }
  for (const auto& light : result.lights)
    for_each_in_square(light.pixel_x, light.pixel_y, half, w, h, [&](int x, int y) { paint(rgb, w, x, y, 255, 0, 0); });
  return rgb;
}

std::vector<uint8_t> plot_lights(const Image& map, const MedianCutResult& result, int half, const ToneMap& tone) {
  Image dots(map.width(), map.height());
  double brightest = 0;
  for (const auto& light : result.lights)
    brightest = std::max({brightest, light.power[0], light.power[1], light.power[2]});
  if (brightest > 0)
    for (const auto& light : result.lights) {
      const Rgb colour{float(light.power[0] / brightest), float(light.power[1] / brightest),
                       float(light.power[2] / brightest)};
      for_each_in_square(light.pixel_x, light.pixel_y, half, map.width(), map.height(),
                         [&](int x, int y) { dots.set(x, y, colour); });
    }
  return tone_map_rgb8(dots, tone);
}

}  // namespace


int median_cut_dot_half_size(int64_t pixel_count, size_t light_count) {
  return pixel_count >= 400 * int64_t(light_count) ? 2 : 1;
}

std::vector<uint8_t> plot_median_cut(const Image& map, const MedianCutResult& result, MedianCutStyle style,
                                     const ToneMap& tone) {
  const int half = median_cut_dot_half_size(map.pixel_count(), result.lights.size());
  return style == MedianCutStyle::Regions ? plot_regions(map, result, half, tone) : plot_lights(map, result, half, tone);
}

}  // namespace lp

#include "engine/sun/sun_core.hpp"

#include <deque>

#include "engine/envmap/latlong.hpp"

namespace lp {
namespace {

// The neighbour of (x, y) at (dx, dy): wrapping in longitude, and over a pole into the same row half
// a turn away.
PixelPos neighbour(PixelPos p, int dx, int dy, int width, int height) {
  int x = p.x + dx, y = p.y + dy;
  if (y < 0 || y >= height) {
    y = p.y;
    x += width / 2;
  }
  return {((x % width) + width) % width, y};
}

}  // namespace

SunCore grow_sun_core(const Image& image, LuminanceMode mode, PixelPos peak, float level,
                      double max_solid_angle) {
  const int w = image.width(), h = image.height();
  std::vector<double> row_omega(static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) row_omega[size_t(y)] = latlong::pixel_solid_angle(y, w, h);
  std::vector<bool> seen(size_t(w) * size_t(h), false);
  const auto index = [w](PixelPos p) { return size_t(p.y) * size_t(w) + size_t(p.x); };

  SunCore core;
  std::deque<PixelPos> queue{peak};
  seen[index(peak)] = true;
  while (!queue.empty()) {
    const PixelPos p = queue.front();
    queue.pop_front();
    core.pixels.push_back(p);
    core.solid_angle += row_omega[size_t(p.y)];
    if (core.solid_angle > max_solid_angle) return core;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const PixelPos n = neighbour(p, dx, dy, w, h);
        if (seen[index(n)] || luminance(image.at(n.x, n.y), mode) < level) continue;
        seen[index(n)] = true;
        queue.push_back(n);
      }
  }
  core.complete = true;
  return core;
}

int64_t sun_core_scratch_bytes(int64_t width, int64_t height) {
  return width * height / 8 + height * int64_t(sizeof(double));
}

}  // namespace lp

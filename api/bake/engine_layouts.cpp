#include "api/bake/engine_layouts.hpp"

#include <cmath>

namespace lp::api {

Image panorama_columns(const Image& latlong, PanoramaColumns columns) {
  const int w = latlong.width(), h = latlong.height();
  Image out(w, h);
  for (int x = 0; x < w; ++x) {
    // The source position of this column's centre, in pixels from the left edge of pixel 0's centre.
    const double u = (double(x) + 0.5) / w;
    double source = (u - columns.offset) * columns.sign;
    source = (source - std::floor(source)) * w - 0.5;
    const double left = std::floor(source);
    const float t = float(source - left);
    const int x0 = (int(left) % w + w) % w, x1 = (x0 + 1) % w;
    for (int y = 0; y < h; ++y) {
      const Rgb a = latlong.at(x0, y), b = latlong.at(x1, y);
      out.set(x, y, t < 1e-6f ? a : a * (1 - t) + b * t);
    }
  }
  return out;
}

Image cube_strip_x_mirrored(const Image& strip) {
  const int n = strip.height();
  Image out(strip.width(), n);
  for (int face = 0; face < 6; ++face) {
    const int from = face < 2 ? 1 - face : face;  // +X and -X exchanged
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) out.set(face * n + x, y, strip.at(from * n + (n - 1 - x), y));
  }
  return out;
}

}  // namespace lp::api

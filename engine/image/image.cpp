#include "engine/image/image.hpp"

#include <algorithm>

#include "engine/core/error.hpp"

namespace lp {

Image::Image(int width, int height) : width_(width), height_(height) {
  if (width < 0 || height < 0) throw Error(ErrorKind::InvalidArgument, "image size must not be negative");
  data_.assign(size_t(width) * size_t(height) * 3, 0.0f);
}

// Each destination pixel averages the source pixels its footprint covers (nearest when enlarging).
Image resize_box(const Image& src, int width, int height) {
  Image dst(width, height);
  for (int y = 0; y < height; ++y) {
    const int y0 = int(int64_t{y} * src.height() / height);
    const int y1 = std::max(y0 + 1, int(int64_t{y + 1} * src.height() / height));
    for (int x = 0; x < width; ++x) {
      const int x0 = int(int64_t{x} * src.width() / width);
      const int x1 = std::max(x0 + 1, int(int64_t{x + 1} * src.width() / width));
      Rgb sum;
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx) sum += src.at(sx, sy);
      dst.set(x, y, sum / float((y1 - y0) * (x1 - x0)));
    }
  }
  return dst;
}

}  // namespace lp

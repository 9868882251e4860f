#include "engine/image/resize.hpp"

#include <stb_image_resize.h>

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace lp {

Size2 fitted_size(int width, int height, std::optional<int> longest) {
  if (!longest || *longest >= std::max(width, height)) return {width, height};
  if (*longest < 1) throw Error(ErrorKind::InvalidArgument, "size must be at least 1");
  const double scale = double(*longest) / double(std::max(width, height));
  const auto side = [scale](int n) { return std::max(1, int(std::lround(double(n) * scale))); };
  return {side(width), side(height)};
}

Image downscale(const Image& image, Size2 size) {
  if (size == Size2{image.width(), image.height()}) return image;
  if (size.width < 1 || size.height < 1 || size.width > image.width() || size.height > image.height())
    throw Error(ErrorKind::InvalidArgument, "downscale: the size must be within the image's");
  Image out(size.width, size.height);
  const int channels = 3;
  if (!stbir_resize_float_generic(image.data().data(), image.width(), image.height(), 0, out.data().data(),
                                  size.width, size.height, 0, channels, STBIR_ALPHA_CHANNEL_NONE, 0,
                                  STBIR_EDGE_CLAMP, STBIR_FILTER_MITCHELL, STBIR_COLORSPACE_LINEAR, nullptr))
    throw Error(ErrorKind::Internal, "cannot resize the image");
  // The filter's negative lobes can undershoot next to a bright edge; radiance is never negative.
  for (float& v : out.data()) v = std::max(v, 0.0f);
  return out;
}

Image fit_longest_side(const Image& image, std::optional<int> longest) {
  return downscale(image, fitted_size(image.width(), image.height(), longest));
}

}  // namespace lp

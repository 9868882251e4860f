#pragma once
// Downscaling for thumbnails: in linear light, before tone mapping, so a bright highlight keeps its
// share of energy in the smaller picture (resizing display values darkens it).
#include <optional>

#include "engine/image/image.hpp"

namespace lp {

struct Size2 {
  int width = 0;
  int height = 0;
  bool operator==(const Size2&) const = default;
};

// The size of a width x height picture whose longest side is at most `longest`, the aspect kept (each
// side rounded, at least 1): never larger than the picture; the picture's own size without `longest`.
Size2 fitted_size(int width, int height, std::optional<int> longest);

// `image` resampled to `size` with a Mitchell-Netravali filter (stb_image_resize) over linear radiance;
// a copy when the size is the image's.
Image downscale(const Image& image, Size2 size);

// downscale to fitted_size(..., longest).
Image fit_longest_side(const Image& image, std::optional<int> longest);

}  // namespace lp

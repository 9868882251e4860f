#pragma once
// Images and maps of one radiance everywhere: the white furnace and its tinted variants.
#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"

namespace lp::test {

inline Image constant_image(int width, int height, Rgb value) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, value);
  return image;
}

inline EnvMap constant_map(int width, int height, Rgb value) {
  return EnvMap(constant_image(width, height, value));
}

}  // namespace lp::test

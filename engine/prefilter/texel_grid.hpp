#pragma once
// Where the texels of an output image look: the direction through each texel's centre. A prefiltered
// level is filled over any grid: a lat-long level, the strip of a cube's six faces, a square map.
#include <functional>

#include "engine/core/vec3.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/projection/projection_texels.hpp"

namespace lp {

struct TexelGrid {
  int width = 0, height = 0;
  std::function<Vec3(int x, int y)> direction;
};

inline TexelGrid latlong_grid(int width, int height) {
  return {width, height, [width, height](int x, int y) {
            return latlong::direction({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)});
          }};
}

// The texel centres of an image of `shape` laid out in `projection` (projection_texels.hpp); not a
// cross, whose empty cells look nowhere.
inline TexelGrid projection_grid(Projection projection, ImageShape shape) {
  if (projection == Projection::LatLong) return latlong_grid(shape.width, shape.height);
  return {shape.width, shape.height, [projection, shape](int x, int y) {
            return to_float(texel_centre_direction(projection, shape, x, y));
          }};
}

}  // namespace lp

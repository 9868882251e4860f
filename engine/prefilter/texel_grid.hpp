#pragma once
// Where the texels of an output image look: the direction through each texel's centre. A prefiltered
// level is filled over any grid; a lat-long level is one, and the faces of a cube map or an octahedral
// square are others.
#include <functional>

#include "engine/core/vec3.hpp"
#include "engine/envmap/latlong.hpp"

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

}  // namespace lp

#include "engine/sh/sh_image.hpp"

#include <tbb/parallel_for.h>

#include "engine/envmap/latlong.hpp"

namespace lp {

Image sh_reconstruction_image(const ShCoefficients& c, int width, int height) {
  Image image(width, height);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Vec3 d =
          latlong::direction({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)});
      const ShRgb v = c.evaluate(d.x, d.y, d.z);
      image.set(x, y, {float(v[0]), float(v[1]), float(v[2])});
    }
  });
  return image;
}

}  // namespace lp

#include "engine/image/tone/curves.hpp"

namespace lp::tone {

Vec3 reinhard(Vec3 rgb) {
  return {rgb.x / (1.0f + rgb.x), rgb.y / (1.0f + rgb.y), rgb.z / (1.0f + rgb.z)};
}

}  // namespace lp::tone

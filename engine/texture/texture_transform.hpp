#pragma once
// KHR_texture_transform: texture coordinates scaled, then rotated, then offset, before the lookup.
#include <cmath>

#include "engine/core/point2.hpp"

namespace lp {

struct TextureTransform {
  Point2 offset{0, 0};
  float rotation = 0;  // radians, counter-clockwise about the UV origin (u right, v up)
  Point2 scale{1, 1};

  bool identity() const {
    return offset.x == 0 && offset.y == 0 && rotation == 0 && scale.x == 1 && scale.y == 1;
  }

  // uv' = T * R * S * uv as the extension writes it in GLSL, whose mat3(cos, sin, 0, -sin, cos, 0, ...)
  // lists columns: u' = cos u - sin v, v' = sin u + cos v after scaling, then the offset.
  Point2 apply(Point2 uv) const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    const float u = uv.x * scale.x, v = uv.y * scale.y;
    return {c * u - s * v + offset.x, s * u + c * v + offset.y};
  }
};

}  // namespace lp

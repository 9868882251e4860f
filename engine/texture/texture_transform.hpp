#pragma once
// KHR_texture_transform: texture coordinates scaled, then rotated, then offset, before the lookup.
#include <cmath>

#include "engine/core/point2.hpp"

namespace lp {

struct TextureTransform {
  Point2 offset{0, 0};
  float rotation = 0;  // radians: the UVs turn counter-clockwise as drawn with v down (the image clockwise)
  Point2 scale{1, 1};

  bool identity() const {
    return offset.x == 0 && offset.y == 0 && rotation == 0 && scale.x == 1 && scale.y == 1;
  }

  // uv' = T * R * S * uv with the rows of R (cos, sin) and (-sin, cos): u' = cos u + sin v,
  // v' = -sin u + cos v after scaling, then the offset. This is the rotation the extension's text, its
  // example (offset (0, 1), rotation pi/2 and scale 0.5 read the lower-left quadrant) and the
  // TextureTransformTest sample's markers define; the GLSL listing's mat3, read column-major, is its
  // transpose (an erratum of the listing, KhronosGroup/glTF issue 1563).
  Point2 apply(Point2 uv) const {
    const Point2 p = apply_to_vector(uv);
    return {p.x + offset.x, p.y + offset.y};
  }
  // A difference of two texture coordinates (a footprint's axis): scaled and rotated, not offset.
  Point2 apply_to_vector(Point2 d) const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    const float u = d.x * scale.x, v = d.y * scale.y;
    return {c * u + s * v, -s * u + c * v};
  }
};

}  // namespace lp

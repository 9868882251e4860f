#pragma once
// How the desktop engines' importers lay out an environment: their frames against our world (z-up,
// right-handed), the columns of their lat-long panoramas and the faces of a left-handed engine's cube.
// Each engine keeps the world's up as its own, so its panorama is ours with the columns reordered.
#include "engine/image/image.hpp"

namespace lp::api {

// A panorama whose column at u (pixel centre (x + 0.5) / W, row 0 the engine's up as in ours) shows our
// map's column at u_ours, with u = sign * u_ours + offset (mod 1).
struct PanoramaColumns {
  int sign;
  double offset;
};

// Our lat-long map (CONTRIBUTING's convention) re-laid as `columns`: exact (columns copied) when
// offset * W is whole, linear between the two nearest columns otherwise.
Image panorama_columns(const Image& latlong, PanoramaColumns columns);

// A cube strip (the six N x N faces side by side, +X, -X, +Y, -Y, +Z, -Z of cube_face.hpp, in the y-up
// frame engine_cube = (x, z, -y)) as a left-handed engine whose frame is that one with x negated samples
// it: +X and -X exchanged and every face mirrored left to right.
Image cube_strip_x_mirrored(const Image& strip);

}  // namespace lp::api

#pragma once
// Where the faces of a cube lie in its two images: the strip (6N x N, the faces side by side in the order
// of cube_face.hpp) and the horizontal cross (4N x 3N):
//
//          py
//      nx  pz  px  nz
//          ny
//
// Each face keeps its orientation of cube_face.hpp, so the cross unfolds the cube seen from inside: the
// middle row runs round the horizon with the sky above it, and neighbouring cells share their edge.
// The six other cells of a cross are black.
#include <optional>

#include "engine/image/image.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

// A texel of a face: face, column i and row j in [0, size).
struct FaceTexel {
  int face = 0, i = 0, j = 0;
};

// The face texel at pixel (x, y) of a cube strip or cross of face `size`; nullopt for the empty cells of
// a cross.
std::optional<FaceTexel> cube_layout_texel(Projection layout, int size, int x, int y);
// The pixel of a face texel in a strip or cross.
Pixel cube_layout_pixel(Projection layout, int size, FaceTexel t);

// The same faces in the other layout (a cross from a strip or a strip from a cross).
Image cube_relayout(const Image& faces, Projection from, Projection to);
// One face of a strip, size x size.
Image cube_strip_face(const Image& strip, int face);

}  // namespace lp

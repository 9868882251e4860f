#pragma once
// The projections a map can be laid out in, and the image shape of each. The conventions of every
// mapping are stated in its own header: latlong in engine/envmap/latlong.hpp, the cube faces in
// cube_face.hpp and their layouts in cube_layout.hpp, the squares in octahedral.hpp and equal_area.hpp.
//
// A projection's `size` is the width of a lat-long map (its height is width / 2), the face size of a
// cube or cross, or the side of an octahedral or equal-area square:
//   latlong     size x size/2
//   cube        6 size x size: the six faces side by side, in the order of cube_face.hpp
//   cross       4 size x 3 size: the horizontal cross of cube_layout.hpp, black outside the faces
//   octahedral  size x size
//   equal-area  size x size
//
// Both square maps share one layout: pixel (x, y) of an N x N square covers u in [2x/N - 1, 2(x+1)/N - 1]
// and v likewise with the row y, row 0 at the top (v = -1); the upper hemisphere (z >= 0) fills the
// diamond |u| + |v| <= 1, the lower one the four corners, the south pole at each corner; u has the sign
// of x and v the sign of y. This is pbrt-v4's layout of its equal-area environment maps.
#include <array>
#include <optional>

#include "engine/core/enum_table.hpp"

namespace lp {

enum class Projection { LatLong, Cube, Cross, Octahedral, EqualArea };
constexpr auto enum_entries(Projection) {
  return std::to_array<EnumEntry<Projection>>({{Projection::LatLong, "latlong"},
                                               {Projection::Cube, "cube"},
                                               {Projection::Cross, "cross"},
                                               {Projection::Octahedral, "octahedral"},
                                               {Projection::EqualArea, "equal-area"}});
}

struct ImageShape {
  int width = 0, height = 0;
};
struct Pixel {
  int x = 0, y = 0;
};

// The image of a projection at `size`.
ImageShape projection_shape(Projection projection, int size);
// The size of an image of width x height in the projection, or nullopt if its shape does not fit: a cube
// is 6:1, a cross 4:3, a square map square; any lat-long image fits (its size is its width).
std::optional<int> projection_size(Projection projection, int width, int height);
// What projection_size asks of a shape, for messages: "4:3 (4N x 3N pixels)".
const char* projection_shape_rule(Projection projection);

// The square coordinate (u or v) of a pixel coordinate of a square map `size` wide (square_coordinate(x +
// 0.5) is the centre of pixel x).
constexpr double square_coordinate(double pixel, int size) {
  return 2 * pixel / size - 1;
}

// Sizes that hold a map at about the same resolution as a lat-long map `latlong_width` wide: the face
// of a cube or cross is a quarter of it (four faces round the horizon), the side of a square map half.
int equivalent_size(Projection projection, int latlong_width);
// The inverse: the width of the lat-long map matching a projection at `size` (4 size for a cube or cross,
// 2 size for a square map).
int equivalent_latlong_width(Projection projection, int size);

}  // namespace lp

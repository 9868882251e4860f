#pragma once
// Directions and texels of every projection, for an image of `shape` laid out in it (a lat-long map may
// have any shape; the others fit projection_size).
#include "engine/image/image.hpp"
#include "engine/projection/geometry.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

// The unit direction through the centre of pixel (x, y); the zero vector for an empty cell of a cross.
Vec3d texel_centre_direction(Projection projection, ImageShape shape, int x, int y);
// The pixel a direction (of any length) falls in.
Pixel texel_containing(Projection projection, ImageShape shape, Vec3d direction);
// The solid angle of pixel (x, y): exact formulas for lat-long rows, cube texels (the same on every face)
// and equal-area texels (4 pi / N^2); an octahedral texel's spherical polygon (its sides are great-circle
// arcs between its corners and folds); 0 for an empty cell of a cross.
double texel_solid_angle(Projection projection, ImageShape shape, int x, int y);
// The power of a map: the sum of radiance times texel solid angle.
Rgb projected_power(const Image& image, Projection projection);

}  // namespace lp

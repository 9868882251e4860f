#pragma once
// Clarberg's equal-area map of the sphere onto a square (P. Clarberg 2008, "Fast Equal-Area Mapping of
// the (Hemi)Sphere using SIMD"), the parameterisation pbrt-v4 requires of its environment maps. Pixel
// layout: engine/projection/projection.hpp.
//
// In the quadrant of (|u|, |v|), let r = |u| + |v| on the diamond |u| + |v| <= 1 (the upper hemisphere)
// and r = 2 - |u| - |v| outside it (the lower one). Then |z| = 1 - r^2, the azimuth within the quadrant is
// phi = (pi / 4) ((|v| - |u|) / r + 1), and the distance from the z axis is r sqrt(2 - r^2); x and y take
// the signs of u and v. Equal squares of (u, v) cover equal solid angles: a pixel of an N x N map covers
// 4 pi / N^2 steradians.
#include "engine/projection/geometry.hpp"

namespace lp::equal_area {

// (u, v) in [-1, 1]^2 of a direction of any length.
Point2d square(Vec3d direction);
// The unit direction of (u, v).
Vec3d direction(Point2d uv);

}  // namespace lp::equal_area

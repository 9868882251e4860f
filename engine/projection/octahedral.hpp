#pragma once
// The octahedral map (Cigolle et al. 2014, "A Survey of Efficient Representations for Independent Unit
// Vectors"): a direction d is projected onto the octahedron |x| + |y| + |z| = 1, p = d / (|x|+|y|+|z|);
// the upper half keeps (u, v) = (p.x, p.y), the lower half is folded out over the diagonals,
// (u, v) = ((1 - |p.y|) sign(p.x), (1 - |p.x|) sign(p.y)). Pixel layout: engine/projection/projection.hpp.
// Inside each of the eight triangles the map is a central projection followed by an affine one, so a
// straight line of the square is a great circle arc there.
#include "engine/projection/geometry.hpp"

namespace lp::octahedral {

// (u, v) in [-1, 1]^2 of a direction of any length.
Point2d square(Vec3d direction);
// The unit direction of (u, v).
Vec3d direction(Point2d uv);
// The point of the octahedron at (u, v) (the direction before normalisation).
Vec3d octahedron_point(Point2d uv);

}  // namespace lp::octahedral

#pragma once
// Per-vertex tangents from texture coordinates, for meshes that come without them. Each triangle's
// tangent and bitangent solve dP = T du + B dv' over its edges (v' = 1 - v, so that B points up the
// image); a vertex sums those of its triangles, weighted by the triangle's area in UV space (the
// solve's determinant), projects the sum onto its normal's plane (Gram-Schmidt) and takes the
// handedness w from which side of cross(n, t) the summed bitangent lies. Vertices with no usable UV
// gradient (all their triangles degenerate in UV, or no UVs) get any unit tangent perpendicular to the
// normal, w = 1. Vertices are not split where UVs mirror, as MikkTSpace would: a vertex shared by
// mirrored triangles gets an averaged tangent.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model.hpp"

namespace lp {

std::vector<Tangent> generate_tangents(std::span<const Vec3> positions, std::span<const Vec3> normals,
                                       std::span<const Point2> uvs, std::span<const uint32_t> indices);

// A unit vector perpendicular to the unit vector `n`.
Vec3 any_perpendicular(Vec3 n);

}  // namespace lp

#pragma once
// Per-vertex tangents from texture coordinates, for meshes that come without them. Each triangle's
// tangent and bitangent solve dP = T du + B dv' over its edges (v' = 1 - v, so that B points up the
// image); a vertex sums those of its triangles, weighted by the triangle's area in UV space (the
// solve's determinant), projects the sum onto its normal's plane (Gram-Schmidt) and takes the
// handedness w from which side of cross(n, t) the summed bitangent lies. Vertices with no usable UV
// gradient (all their triangles degenerate in UV, or no UVs) get any unit tangent perpendicular to the
// normal, w = 1.
//
// Mirrored UVs: a vertex shared by triangles whose UV mappings have opposite handedness (the sign of the
// determinant) would average opposite tangents (a mirror in u) or bitangents (in v) into a zero or
// turned frame. Such vertices are split first, as MikkTSpace does: split_mirrored_vertices gives the
// triangles of the vertex's second handedness a copy of it, so that every vertex sums the tangents of
// one handedness only.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model.hpp"

namespace lp {

// Rewrites `indices` (triangles over `uvs.size()` vertices) so that no vertex is shared by triangles of
// opposite UV handedness. Returns, for each vertex appended, the vertex it copies (vertex
// uvs.size() + k copies result[k]); the caller appends those copies to every per-vertex array.
// Triangles without a UV gradient keep their vertices. Throws lp::Error(TooLarge) past 2^32 vertices.
std::vector<uint32_t> split_mirrored_vertices(std::span<const Point2> uvs, std::span<uint32_t> indices);

// No vertex may be shared by triangles of opposite UV handedness (split_mirrored_vertices first).
std::vector<Tangent> generate_tangents(std::span<const Vec3> positions, std::span<const Vec3> normals,
                                       std::span<const Point2> uvs, std::span<const uint32_t> indices);

// A unit vector perpendicular to the unit vector `n`.
Vec3 any_perpendicular(Vec3 n);

}  // namespace lp

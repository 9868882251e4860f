#pragma once
// Polygons on the unit sphere whose sides are great-circle arcs, given by their corners as directions of
// any length (the chord between two corners lies in the plane of their great circle, so clipping the
// chords by a plane through the centre clips the arcs).
#include <initializer_list>
#include <span>
#include <vector>

#include "engine/projection/geometry.hpp"

namespace lp {

using SphericalPolygon = std::vector<Vec3d>;

// The solid angle a polygon encloses: positive when its corners turn counter-clockwise seen from outside
// the sphere, negative when clockwise. Exact (a sum of spherical triangles) for polygons within a
// hemisphere around their mean direction.
double spherical_polygon_area(std::span<const Vec3d> corners);

// The part of `in` on the side of the plane through the centre where dot(p, normal) >= 0, into `out`.
void clip_to_hemisphere(std::span<const Vec3d> in, Vec3d normal, SphericalPolygon& out);
// The part of `in` inside all the hemispheres, into `out` (`spare` is a buffer); false if nothing is.
bool clip_to_hemispheres(std::span<const Vec3d> in, std::initializer_list<Vec3d> normals,
                         SphericalPolygon& out, SphericalPolygon& spare);

}  // namespace lp

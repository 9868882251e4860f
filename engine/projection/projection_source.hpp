#pragma once
// A map in one projection read as the source of a resampling. Each source texel's radiance is taken as
// constant over its area on the sphere, and integrate() adds, for every piece of a target texel lying
// over a source texel, the radiance times the piece's solid angle. The pieces are cut in a plane where
// the source texels are rectangles: (longitude, -z) for a lat-long map, where area is solid angle; the
// plane of each cube face, where straight lines are great circles and a piece's solid angle is that of its
// spherical polygon; the square of the octahedral map (the same, inside each octant) and of the
// equal-area map (area times pi). A target texel's polygon is drawn in that plane with straight sides
// between its boundary points, so neighbouring texels share their sides: the pieces of all the target
// texels tile every source texel exactly, and each source texel gives away exactly its own power.
#include <memory>
#include <span>

#include "engine/core/constants.hpp"
#include "engine/image/image.hpp"
#include "engine/projection/grid_clip.hpp"
#include "engine/projection/grid_coverage.hpp"
#include "engine/projection/projection.hpp"
#include "engine/projection/spherical_polygon.hpp"
#include "engine/projection/target_panels.hpp"

namespace lp {

// Sums over the pieces of one target texel.
struct TexelSum {
  double r = 0, g = 0, b = 0, area = 0;
  void add(const float* rgb, double piece_area) {
    r += rgb[0] * piece_area, g += rgb[1] * piece_area, b += rgb[2] * piece_area;
    area += piece_area;
  }
};

// Reused buffers, one per thread.
struct SourceScratch {
  GridClipScratch grid;
  GridCoverage coverage;
  PlanePolygon plane;
  SphericalPolygon clipped, spare, lifted;
};

class ProjectionSource : public EdgeRule {
 public:
  // Sides longer than this angle are cut (0.5 degrees: the area a straight side misses of a curved one
  // shrinks with the square of its length).
  static constexpr double kMaxSideRadians = 0.5 * kPi / 180;

  bool needs_split(Vec3d a, Vec3d b) const override;
  // Adds the pieces of a target texel, given by its outline (target_panels.hpp): unit directions in order.
  virtual void integrate(std::span<const Vec3d> polygon, SourceScratch& scratch, TexelSum& sum) const = 0;
};

// `image` must fit the projection's shape (projection_size); it must outlive the source.
std::unique_ptr<const ProjectionSource> make_projection_source(const Image& image, Projection projection);

}  // namespace lp

// An octahedral or equal-area square as a resampling source. Both fold the lower hemisphere out over the
// diamond's edges, so a polygon is first cut into its parts in the eight octants; each part is drawn in
// its octant's triangle of the square. On the octahedral square straight lines are great circles inside
// a triangle and a piece's solid angle is its spherical polygon's; the equal-area square's area is solid
// angle (times pi: the square [-1, 1]^2 has area 4).
#include <array>

#include "engine/core/constants.hpp"
#include "engine/projection/equal_area.hpp"
#include "engine/projection/octahedral.hpp"
#include "engine/projection/source_charts.hpp"

namespace lp {
namespace {

// An octant: the signs of x, y and z.
struct Octant {
  double x, y, z;
};

Octant octant_of(Vec3d p) {
  return {p.x < 0 ? -1.0 : 1.0, p.y < 0 ? -1.0 : 1.0, p.z < 0 ? -1.0 : 1.0};
}

bool same_octant(Octant a, Octant b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

class SquareSource final : public ProjectionSource {
 public:
  SquareSource(const Image& image, Projection projection)
      : image_(image),
        equal_area_(projection == Projection::EqualArea),
        axis_(GridAxis::uniform(-1, 2.0 / image.width(), image.width())) {}

  void integrate(std::span<const Vec3d> polygon, SourceScratch& s, TexelSum& sum) const override {
    const Octant octant = octant_of(polygon[0]);
    bool one_octant = true;
    for (const Vec3d& p : polygon) one_octant = one_octant && same_octant(octant_of(p), octant);
    if (one_octant) return integrate_in_octant(octant, polygon, s, sum, true);
    for (int k = 0; k < 8; ++k) {
      const Octant o{k & 1 ? -1.0 : 1.0, k & 2 ? -1.0 : 1.0, k & 4 ? -1.0 : 1.0};
      if (clip_to_hemispheres(polygon, {Vec3d{o.x, 0, 0}, Vec3d{0, o.y, 0}, Vec3d{0, 0, o.z}}, s.clipped,
                              s.spare))
        integrate_in_octant(o, s.clipped, s, sum, false);
    }
  }

 private:
  // The point of the square for a direction in the octant: mapped in the octant of positive x and y, so
  // a point a clip left a rounding error off the octant's planes stays on the octant's side of the fold.
  Point2d square(Octant o, Vec3d p) const {
    const Vec3d q{std::max(0.0, o.x * p.x), std::max(0.0, o.y * p.y), o.z * std::max(0.0, o.z * p.z)};
    const Point2d uv = equal_area_ ? equal_area::square(q) : octahedral::square(q);
    return {o.x * uv.x, o.y * uv.y};
  }

  double piece_area(Octant o, const PlanePolygon& piece, SourceScratch& s) const {
    s.lifted.clear();
    for (const Point2d& uv : piece) {
      const Vec3d q = octahedral::octahedron_point({std::max(0.0, o.x * uv.x), std::max(0.0, o.y * uv.y)});
      s.lifted.push_back({o.x * q.x, o.y * q.y, q.z});
    }
    return spherical_polygon_area(s.lifted);
  }

  // `whole`: as CubeSource's integrate_on_face.
  void integrate_in_octant(Octant o, std::span<const Vec3d> polygon, SourceScratch& s, TexelSum& sum,
                           bool whole) const {
    s.plane.clear();
    for (const Vec3d& p : polygon) s.plane.push_back(square(o, p));
    if (equal_area_)
      return s.coverage.cover(s.plane, axis_, axis_,
                              [&](int i, int j, double area) { sum.add(image_.row(j) + 3 * i, area * kPi); });
    for_each_cell_piece(s.plane, axis_, axis_, s.grid, [&](int i, int j, const PlanePolygon& piece) {
      if (whole && &piece == &s.plane) return sum.add(image_.row(j) + 3 * i, 1.0);
      const double area = piece_area(o, piece, s);
      if (area != 0) sum.add(image_.row(j) + 3 * i, area);
    });
  }

  const Image& image_;
  bool equal_area_;
  GridAxis axis_;
};

}  // namespace

std::unique_ptr<const ProjectionSource> make_square_source(const Image& image, Projection projection) {
  return std::make_unique<SquareSource>(image, projection);
}

}  // namespace lp

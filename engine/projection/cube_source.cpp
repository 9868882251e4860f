// A cube map (strip or cross) as a resampling source. A polygon is cut by the four planes bounding each
// face it reaches and drawn on that face's plane, where the texel grid is square and straight lines are
// great circles: each piece's solid angle is its spherical polygon's.
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/source_charts.hpp"

namespace lp {
namespace {

class CubeSource final : public ProjectionSource {
 public:
  CubeSource(const Image& image, Projection layout)
      : strip_(layout == Projection::Cube ? Image() : cube_relayout(image, layout, Projection::Cube)),
        faces_(layout == Projection::Cube ? image : strip_),
        size_(faces_.height()),
        axis_(GridAxis::uniform(-1, 2.0 / size_, size_)) {}

  void integrate(std::span<const Vec3d> polygon, SourceScratch& s, TexelSum& sum) const override {
    const int face = cube_face_point(polygon[0]).face;
    bool one_face = true;
    for (const Vec3d& p : polygon) one_face = one_face && cube_face_point(p).face == face;
    if (one_face) return integrate_on_face(face, polygon, s, sum, true);
    for (int f = 0; f < kCubeFaces; ++f) {
      const CubeFaceFrame& frame = cube_face_frame(f);
      if (clip_to_hemispheres(polygon,
                              {frame.look - frame.right, frame.look + frame.right, frame.look - frame.down,
                               frame.look + frame.down},
                              s.clipped, s.spare))
        integrate_on_face(f, s.clipped, s, sum, false);
    }
  }

 private:
  // `whole`: the polygon is the whole target texel. If it then lies in one source texel, it takes that
  // texel's value whatever its area, which is not worked out.
  void integrate_on_face(int face, std::span<const Vec3d> polygon, SourceScratch& s, TexelSum& sum,
                         bool whole) const {
    const CubeFaceFrame& frame = cube_face_frame(face);
    s.plane.clear();
    for (const Vec3d& p : polygon) {
      const double look = dot(p, frame.look);
      s.plane.push_back({dot(p, frame.right) / look, dot(p, frame.down) / look});
    }
    for_each_cell_piece(s.plane, axis_, axis_, s.grid, [&](int i, int j, const PlanePolygon& piece) {
      if (whole && &piece == &s.plane) return sum.add(faces_.row(j) + 3 * (face * size_ + i), 1.0);
      s.lifted.clear();
      for (const Point2d& ab : piece) s.lifted.push_back(cube_face_direction(face, ab));
      const double area = spherical_polygon_area(s.lifted);
      if (area != 0) sum.add(faces_.row(j) + 3 * (face * size_ + i), area);
    });
  }

  Image strip_;         // the faces as a strip, when the source is a cross
  const Image& faces_;  // the strip read from
  int size_;
  GridAxis axis_;
};

}  // namespace

std::unique_ptr<const ProjectionSource> make_cube_source(const Image& image, Projection layout) {
  return std::make_unique<CubeSource>(image, layout);
}

}  // namespace lp

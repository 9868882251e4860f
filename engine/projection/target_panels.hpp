#pragma once
// The texels of a projection as the targets of a resampling, in rectangular panels: a lat-long map or a
// square map is one panel, a cube six (its faces, placed in a strip or a cross). A point of a panel is
// given in texel units: texel (i, j) spans [i, i + 1] x [j, j + 1].
//
// A texel's outline is its corners, in order round it, with points added along a side where the source's
// EdgeRule asks (the straight side the source draws between two points stands for a curve, and is kept
// short enough to follow it) and where a side crosses a fold of a square map (its axes and the diamond
// |u| + |v| = 1). Neighbouring texels add the same points to the side they share.
#include <array>
#include <vector>

#include "engine/projection/projection.hpp"
#include "engine/projection/spherical_polygon.hpp"

namespace lp {

// Whether the side of a texel between two points (unit directions) must be cut in two.
class EdgeRule {
 public:
  virtual ~EdgeRule() = default;
  virtual bool needs_split(Vec3d a, Vec3d b) const = 0;
};

// Cuts nothing: the outline through the corners (and the folds) alone.
class NoEdgeSplits final : public EdgeRule {
 public:
  bool needs_split(Vec3d, Vec3d) const override { return false; }
};

class TargetPanel {
 public:
  static std::vector<TargetPanel> of(Projection projection, int size);

  int width() const { return width_; }
  int height() const { return height_; }
  Pixel origin() const { return origin_; }  // where texel (0, 0) lies in the projection's image

  // The unit direction of a point of the panel.
  Vec3d direction(Point2d p) const;
  // The directions of the corners (i, j), i = 0 .. width, into `out`.
  void corner_row(int j, std::vector<Vec3d>& out) const;
  // The outline of texel (i, j) from its corners (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j).
  void outline(int i, int j, const std::array<Vec3d, 4>& corners, const EdgeRule& rule,
               SphericalPolygon& out) const;

 private:
  TargetPanel(Projection projection, int face, int width, int height, Pixel origin);
  void add_side(Point2d a, Vec3d da, Point2d b, Vec3d db, const EdgeRule& rule, int depth,
                SphericalPolygon& out) const;

  Projection projection_;
  int face_;
  int width_, height_;
  Pixel origin_;
  std::vector<double> sin_theta_, cos_theta_, sin_phi_, cos_phi_;  // a lat-long panel's corner rows
};

// The outline of pixel (x, y) of a projection's image at `size`; false for an empty cell of a cross.
bool texel_outline(Projection projection, int size, int x, int y, const EdgeRule& rule,
                   SphericalPolygon& out);

}  // namespace lp

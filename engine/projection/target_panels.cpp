#include "engine/projection/target_panels.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/equal_area.hpp"
#include "engine/projection/octahedral.hpp"

namespace lp {
namespace {

// Halving a side more often than this stops (a side split 2^12 times is shorter than any texel).
constexpr int kMaxSplitDepth = 12;

// The points of a side: its ends and, between them, where it crosses a fold.
struct SidePoints {
  std::array<Point2d, 8> at;
  size_t count = 0;
  void add(Point2d p) { at[count++] = p; }
};

// Where the side from a to b (parallel to an axis) of an n x n square map crosses a fold: in texel units
// the axes are x or y = n/2 and the diamond's sides x + y = n/2 or 3n/2 and x - y = +-n/2, all exact.
void add_fold_crossings(Point2d a, Point2d b, int n, SidePoints& out) {
  const bool along_x = a.y == b.y;
  const double fixed = along_x ? a.y : a.x, from = along_x ? a.x : a.y, to = along_x ? b.x : b.y;
  const double h = n / 2.0;
  std::array<double, 5> at = {h, 3 * h - fixed, h - fixed, fixed + h, fixed - h};
  std::sort(at.begin(), at.end());
  if (to < from) std::reverse(at.begin(), at.end());
  for (const double c : at)
    if ((c > from && c < to) || (c < from && c > to))
      out.add(along_x ? Point2d{c, fixed} : Point2d{fixed, c});
}

}  // namespace

TargetPanel::TargetPanel(Projection projection, int face, int width, int height, Pixel origin)
    : projection_(projection), face_(face), width_(width), height_(height), origin_(origin) {
  if (projection != Projection::LatLong) return;
  // The same values as direction() gives the corners.
  for (int j = 0; j <= height; ++j) {
    sin_theta_.push_back(std::sin(kPi * j / height));
    cos_theta_.push_back(std::cos(kPi * j / height));
  }
  for (int i = 0; i <= width; ++i) {
    sin_phi_.push_back(std::sin(2 * kPi * i / width));
    cos_phi_.push_back(std::cos(2 * kPi * i / width));
  }
}

std::vector<TargetPanel> TargetPanel::of(Projection projection, int size) {
  const ImageShape shape = projection_shape(projection, size);
  if (projection != Projection::Cube && projection != Projection::Cross)
    return {TargetPanel(projection, 0, shape.width, shape.height, {0, 0})};
  std::vector<TargetPanel> faces;
  for (int face = 0; face < kCubeFaces; ++face)
    faces.push_back(
        TargetPanel(projection, face, size, size, cube_layout_pixel(projection, size, {face, 0, 0})));
  return faces;
}

Vec3d TargetPanel::direction(Point2d p) const {
  const Point2d uv{square_coordinate(p.x, width_), square_coordinate(p.y, height_)};
  switch (projection_) {
    case Projection::LatLong: {
      const double theta = kPi * p.y / height_, phi = 2 * kPi * p.x / width_, s = std::sin(theta);
      return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
    }
    case Projection::Cube:
    case Projection::Cross:
      return normalize(cube_face_direction(face_, uv));
    case Projection::Octahedral:
      return octahedral::direction(uv);
    case Projection::EqualArea:
      return equal_area::direction(uv);
  }
  return {};
}

void TargetPanel::corner_row(int j, std::vector<Vec3d>& out) const {
  out.resize(size_t(width_) + 1);
  for (int i = 0; i <= width_; ++i)
    out[size_t(i)] = projection_ == Projection::LatLong
                         ? Vec3d{sin_theta_[size_t(j)] * cos_phi_[size_t(i)],
                                 sin_theta_[size_t(j)] * sin_phi_[size_t(i)], cos_theta_[size_t(j)]}
                         : direction({double(i), double(j)});
}

void TargetPanel::add_side(Point2d a, Vec3d da, Point2d b, Vec3d db, const EdgeRule& rule, int depth,
                           SphericalPolygon& out) const {
  if (depth < kMaxSplitDepth && rule.needs_split(da, db)) {
    const Point2d m{(a.x + b.x) / 2, (a.y + b.y) / 2};
    const Vec3d dm = direction(m);
    add_side(a, da, m, dm, rule, depth + 1, out);
    add_side(m, dm, b, db, rule, depth + 1, out);
  } else {
    out.push_back(da);
  }
}

void TargetPanel::outline(int i, int j, const std::array<Vec3d, 4>& corners, const EdgeRule& rule,
                          SphericalPolygon& out) const {
  const std::array<Point2d, 4> at = {Point2d{double(i), double(j)}, Point2d{double(i), double(j + 1)},
                                     Point2d{double(i + 1), double(j + 1)},
                                     Point2d{double(i + 1), double(j)}};
  const bool square = projection_ == Projection::Octahedral || projection_ == Projection::EqualArea;
  out.clear();
  for (size_t k = 0; k < 4; ++k) {
    const size_t next = (k + 1) % 4;
    if (!square) {  // no folds: the side alone
      add_side(at[k], corners[k], at[next], corners[next], rule, 0, out);
      continue;
    }
    SidePoints side;
    side.add(at[k]);
    add_fold_crossings(at[k], at[next], width_, side);
    side.add(at[next]);
    Vec3d d = corners[k];
    for (size_t s = 1; s < side.count; ++s) {
      const Vec3d e = s + 1 == side.count ? corners[next] : direction(side.at[s]);
      add_side(side.at[s - 1], d, side.at[s], e, rule, 0, out);
      d = e;
    }
  }
}

bool texel_outline(Projection projection, int size, int x, int y, const EdgeRule& rule,
                   SphericalPolygon& out) {
  const std::vector<TargetPanel> panels = TargetPanel::of(projection, size);
  for (const TargetPanel& panel : panels) {
    const int i = x - panel.origin().x, j = y - panel.origin().y;
    if (i < 0 || j < 0 || i >= panel.width() || j >= panel.height()) continue;
    const auto corner = [&](int ci, int cj) { return panel.direction({double(ci), double(cj)}); };
    panel.outline(i, j, {corner(i, j), corner(i, j + 1), corner(i + 1, j + 1), corner(i + 1, j)}, rule, out);
    return true;
  }
  return false;
}

}  // namespace lp

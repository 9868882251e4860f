#include "engine/texture/texture_footprint.hpp"

#include <cmath>

namespace lp {

// With J = [a b], the ellipse is J applied to the unit disc; its squared semi-axes are the eigenvalues
// of J J^T = [[p, r], [r, q]]. The smaller one is taken from det(J)^2 / the larger, which keeps its
// precision for long, thin footprints.
FootprintAxes principal_axes(const UvFootprint& f) {
  const float p = f.a.x * f.a.x + f.b.x * f.b.x, q = f.a.y * f.a.y + f.b.y * f.b.y;
  const float r = f.a.x * f.a.y + f.b.x * f.b.y;
  const float half_diff = 0.5f * (p - q);
  const float largest = 0.5f * (p + q) + std::hypot(half_diff, r);
  FootprintAxes axes;
  axes.major_width = std::sqrt(largest);
  if (!(axes.major_width > 0)) return axes;  // also NaN: a point
  axes.minor_width = std::abs(f.a.x * f.b.y - f.a.y * f.b.x) / axes.major_width;
  // The eigenvector of `largest`: (largest - q, r), or (r, largest - p), whichever is the longer.
  const Point2 u{largest - q, r}, v{r, largest - p};
  const Point2 d = u.x * u.x + u.y * u.y >= v.x * v.x + v.y * v.y ? u : v;
  const float len = std::hypot(d.x, d.y);
  axes.major = len > 0 ? Point2{d.x / len, d.y / len} : Point2{1, 0};
  return axes;
}

}  // namespace lp

#pragma once
// The pixels of a lat-long map near a direction, in double precision: a sun of a quarter degree on an
// 8K map is a few pixels of 0.04 degrees, where a float's dot product near 1 loses the angle.
#include <array>
#include <vector>

namespace lp {

using Direction = std::array<double, 3>;

// The unit direction through the centre of pixel (x, y) (engine/envmap/latlong.hpp).
Direction pixel_centre_direction(int x, int y, int width, int height);
// The angle between unit directions, 2 asin(|a - b| / 2): exact for small angles, unlike acos(a . b).
double angle_between(const Direction& a, const Direction& b);

// The columns of row y that may hold pixels of a cone: `count` columns from x0, wrapping past the last.
struct RowSpan {
  int y = 0, x0 = 0, count = 0;
};
// Row spans covering every pixel whose centre lies within `radius` of the unit `axis` (and a few more:
// callers test each pixel with angle_between). Every column of a row when the cone holds a pole.
std::vector<RowSpan> cone_row_spans(int width, int height, const Direction& axis, double radius);

}  // namespace lp

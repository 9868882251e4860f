#pragma once
// A rectangle of lat-long pixels, half-open: [x0, x1) x [y0, y1).
#include <cstdint>

namespace lp {

struct Region {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  int64_t pixel_count() const { return int64_t{width()} * height(); }
  bool splittable() const { return width() > 1 || height() > 1; }
  bool operator==(const Region&) const = default;
};

}  // namespace lp

#pragma once
// The affine transforms of a glTF node hierarchy: 4 x 4, column-major as glTF stores them, in double.
#include <array>
#include <cmath>

#include "engine/core/vec3.hpp"

namespace lp {

struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // m[col * 4 + row]

  double at(int row, int col) const { return m[size_t(col * 4 + row)]; }

  Mat4 operator*(const Mat4& b) const {
    Mat4 r;
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col) {
        double s = 0;
        for (int k = 0; k < 4; ++k) s += at(row, k) * b.at(k, col);
        r.m[size_t(col * 4 + row)] = s;
      }
    return r;
  }

  // Translation * rotation (unit quaternion x, y, z, w) * scale, glTF's TRS order.
  static Mat4 trs(const std::array<double, 3>& t, const std::array<double, 4>& q,
                  const std::array<double, 3>& s) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Mat4 out;
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) out.m[size_t(col * 4 + row)] = r[row][col] * s[size_t(col)];
      out.m[size_t(12 + row)] = t[size_t(row)];
    }
    return out;
  }

  Vec3 point(Vec3 p) const {
    return {float(at(0, 0) * p.x + at(0, 1) * p.y + at(0, 2) * p.z + at(0, 3)),
            float(at(1, 0) * p.x + at(1, 1) * p.y + at(1, 2) * p.z + at(1, 3)),
            float(at(2, 0) * p.x + at(2, 1) * p.y + at(2, 2) * p.z + at(2, 3))};
  }
  Vec3 vector(Vec3 v) const {
    return {float(at(0, 0) * v.x + at(0, 1) * v.y + at(0, 2) * v.z),
            float(at(1, 0) * v.x + at(1, 1) * v.y + at(1, 2) * v.z),
            float(at(2, 0) * v.x + at(2, 1) * v.y + at(2, 2) * v.z)};
  }
  double determinant3() const {
    return at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
           at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
           at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  }
  // A normal through the inverse transpose of the upper 3 x 3, computed as the cofactor matrix (the
  // inverse transpose times the determinant) times the determinant's sign: the same direction, and
  // defined for singular matrices too. Not normalised.
  Vec3 normal(Vec3 n) const {
    const auto c = [&](int r, int k) {
      const int r0 = (r + 1) % 3, r1 = (r + 2) % 3, k0 = (k + 1) % 3, k1 = (k + 2) % 3;
      return at(r0, k0) * at(r1, k1) - at(r0, k1) * at(r1, k0);
    };
    const double sign = determinant3() < 0 ? -1.0 : 1.0;
    return {float(sign * (c(0, 0) * n.x + c(0, 1) * n.y + c(0, 2) * n.z)),
            float(sign * (c(1, 0) * n.x + c(1, 1) * n.y + c(1, 2) * n.z)),
            float(sign * (c(2, 0) * n.x + c(2, 1) * n.y + c(2, 2) * n.z))};
  }
  bool finite() const {
    for (double v : m)
      if (!std::isfinite(v)) return false;
    return true;
  }
};

}  // namespace lp

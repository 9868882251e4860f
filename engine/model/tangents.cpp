#include "engine/model/tangents.hpp"

#include <cmath>

namespace lp {

Vec3 any_perpendicular(Vec3 n) {
  // Frisvad's / Duff et al.'s branchless orthonormal basis.
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
  return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

std::vector<Tangent> generate_tangents(std::span<const Vec3> positions, std::span<const Vec3> normals,
                                       std::span<const Point2> uvs, std::span<const uint32_t> indices) {
  std::vector<Vec3> t_sum(positions.size()), b_sum(positions.size());
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2];
    const Vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
    const float du1 = uvs[b].x - uvs[a].x, du2 = uvs[c].x - uvs[a].x;
    const float dv1 = uvs[a].y - uvs[b].y, dv2 = uvs[a].y - uvs[c].y;  // v' = 1 - v
    const float det = du1 * dv2 - du2 * dv1;
    if (!(std::abs(det) > 1e-20f)) continue;  // no UV gradient (also NaN)
    // T = (e1 dv2 - e2 dv1) / det and B = (e2 du1 - e1 du2) / det, weighted by |det|.
    const float s = det > 0 ? 1.0f : -1.0f;
    const Vec3 t = (e1 * dv2 - e2 * dv1) * s, bt = (e2 * du1 - e1 * du2) * s;
    if (!finite(t) || !finite(bt)) continue;
    for (uint32_t v : {a, b, c}) t_sum[v] += t, b_sum[v] += bt;
  }
  std::vector<Tangent> tangents(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    const Vec3 n = normals[v];
    const Vec3 t = t_sum[v] - n * dot(n, t_sum[v]);
    const float len = length(t);
    if (!(len > 1e-12f) || !std::isfinite(len)) {
      tangents[v] = {any_perpendicular(n), 1.0f};
      continue;
    }
    tangents[v] = {t / len, dot(cross(n, t), b_sum[v]) < 0 ? -1.0f : 1.0f};
  }
  return tangents;
}

}  // namespace lp

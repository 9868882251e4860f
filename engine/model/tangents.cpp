#include "engine/model/tangents.hpp"

#include <cmath>

#include "engine/core/error.hpp"

namespace lp {
namespace {

// A triangle's UV edges from its first vertex, in (u, v') = (u, 1 - v).
struct UvEdges {
  float du1, du2, dv1, dv2;
  UvEdges(std::span<const Point2> uvs, uint32_t a, uint32_t b, uint32_t c)
      : du1(uvs[b].x - uvs[a].x),
        du2(uvs[c].x - uvs[a].x),
        dv1(uvs[a].y - uvs[b].y),
        dv2(uvs[a].y - uvs[c].y) {}
  // Twice the signed area: its sign is the UV mapping's handedness. 0 where there is no UV gradient
  // (also for NaN).
  float determinant() const {
    const float det = du1 * dv2 - du2 * dv1;
    return std::abs(det) > 1e-20f ? det : 0.0f;
  }
};

}  // namespace

Vec3 any_perpendicular(Vec3 n) {
  // Frisvad's / Duff et al.'s branchless orthonormal basis.
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
  return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

std::vector<uint32_t> split_mirrored_vertices(std::span<const Point2> uvs, std::span<uint32_t> indices) {
  constexpr uint32_t kNone = UINT32_MAX;
  // The handedness a vertex keeps (the first it meets: +1 or -1, 0 before any) and its copy for the other.
  std::vector<int8_t> kept(uvs.size(), 0);
  std::vector<uint32_t> copy(uvs.size(), kNone);
  std::vector<uint32_t> sources;
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const float det = UvEdges(uvs, indices[i], indices[i + 1], indices[i + 2]).determinant();
    if (det == 0) continue;
    const int8_t side = det > 0 ? 1 : -1;
    for (size_t k = i; k < i + 3; ++k) {
      const uint32_t v = indices[k];
      if (kept[v] == 0) kept[v] = side;
      if (kept[v] == side) continue;
      if (copy[v] == kNone) {
        if (uvs.size() + sources.size() >= size_t(UINT32_MAX))
          throw Error(ErrorKind::TooLarge, "model has over 2^32 vertices");
        copy[v] = uint32_t(uvs.size() + sources.size());
        sources.push_back(v);
      }
      indices[k] = copy[v];
    }
  }
  return sources;
}

std::vector<Tangent> generate_tangents(std::span<const Vec3> positions, std::span<const Vec3> normals,
                                       std::span<const Point2> uvs, std::span<const uint32_t> indices) {
  std::vector<Vec3> t_sum(positions.size()), b_sum(positions.size());
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2];
    const UvEdges uv(uvs, a, b, c);
    const float det = uv.determinant();
    if (det == 0) continue;
    const Vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
    // T = (e1 dv2 - e2 dv1) / det and B = (e2 du1 - e1 du2) / det, weighted by |det|.
    const float s = det > 0 ? 1.0f : -1.0f;
    const Vec3 t = (e1 * uv.dv2 - e2 * uv.dv1) * s, bt = (e2 * uv.du1 - e1 * uv.du2) * s;
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

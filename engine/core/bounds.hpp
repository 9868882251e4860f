#pragma once
// Axis-aligned bounds of points, and the sphere around them that framing a view uses.
#include <algorithm>
#include <limits>

#include "engine/core/vec3.hpp"

namespace lp {

struct Bounds {
  Vec3 min{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
           std::numeric_limits<float>::infinity()};
  Vec3 max{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
           -std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x; }
  void extend(Vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
  }
  void extend(const Bounds& b) {
    if (b.empty()) return;
    extend(b.min);
    extend(b.max);
  }
  Vec3 center() const { return (min + max) * 0.5f; }
  bool contains(Vec3 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
  }
};

// A sphere holding a set of points: centred on their bounds, its radius the farthest point's distance.
struct BoundingSphere {
  Vec3 center;
  float radius = 0;
};

}  // namespace lp

#include "engine/model/model.hpp"

#include <algorithm>
#include <cmath>

namespace lp {

int64_t Model::memory_bytes() const {
  int64_t bytes = int64_t(positions.size() * (sizeof(Vec3) * 2 + sizeof(Point2) + sizeof(Tangent)) +
                          indices.size() * sizeof(uint32_t) + triangle_materials.size() * sizeof(uint32_t) +
                          colors.size() * sizeof(Rgba) + uvs1.size() * sizeof(Point2));
  std::vector<const Texture*> counted;
  for (const ModelMaterial& m : materials)
    for (const auto* b : m.bindings())
      if (*b && std::find(counted.begin(), counted.end(), (*b)->texture.get()) == counted.end()) {
        counted.push_back((*b)->texture.get());
        bytes += (*b)->texture->memory_bytes();
      }
  return bytes;
}

Rgb MaterialLobes::absorption() const {
  if (!std::isfinite(attenuation_distance)) return {};
  const auto channel = [this](float c) {
    return c >= 1 ? 0.0f : -std::log(std::max(c, 1e-6f)) / attenuation_distance;
  };
  return {channel(attenuation_color.x), channel(attenuation_color.y), channel(attenuation_color.z)};
}

}  // namespace lp

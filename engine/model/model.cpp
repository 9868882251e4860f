#include "engine/model/model.hpp"

#include <algorithm>
#include <cmath>

namespace lp {

int64_t Model::memory_bytes() const {
  int64_t bytes = int64_t(positions.size() * (sizeof(Vec3) * 2 + sizeof(Point2) + sizeof(Tangent)) +
                          indices.size() * sizeof(uint32_t) + triangle_materials.size() * sizeof(uint32_t));
  std::vector<const Texture*> counted;
  const auto count = [&](const std::optional<TextureBinding>& b) {
    if (b && std::find(counted.begin(), counted.end(), b->texture.get()) == counted.end()) {
      counted.push_back(b->texture.get());
      bytes += b->texture->memory_bytes();
    }
  };
  for (const ModelMaterial& m : materials) {
    for (const auto* b : {&m.base_color, &m.metallic_roughness, &m.normal, &m.emissive}) count(*b);
    if (m.lobes)
      for (const auto* b : m.lobes->textures()) count(*b);
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

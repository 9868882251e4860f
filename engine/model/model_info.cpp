#include "engine/model/model_info.hpp"

#include <algorithm>

#include "engine/model/model_frame.hpp"

namespace lp {
namespace {

// In the world frame: an OBJ's positions as a scene places it by default (model_frame.hpp).
void describe_extent(const Model& model, ModelInfo& info) {
  const Mat4 frame = model.up_axis_unstated ? up_axis_to_world(kDefaultUpAxis) : Mat4{};
  for (const Vec3& p : model.positions) info.bounds.extend(frame.point(p));
  if (info.bounds.empty()) return;
  info.sphere.center = info.bounds.center();
  for (const Vec3& p : model.positions)
    info.sphere.radius = std::max(info.sphere.radius, length(frame.point(p) - info.sphere.center));
}

struct Slot {
  const std::optional<TextureBinding>* binding;
  const char* feature;
  ColorSpace space;
};

std::vector<Slot> slots(const ModelMaterial& m) {
  return {{&m.base_color, "base_color_texture", ColorSpace::Srgb},
          {&m.metallic_roughness, "metallic_roughness_texture", ColorSpace::Linear},
          {&m.normal, "normal_texture", ColorSpace::Linear},
          {&m.emissive, "emissive_texture", ColorSpace::Srgb}};
}

MaterialInfo material_info(const ModelMaterial& m, const ModelSource::Material* source) {
  MaterialInfo out{m.name, {}, {}};
  for (const Slot& s : slots(m))
    if (*s.binding) out.features.push_back(s.feature);
  if (max_component(m.emissive_factor) > 0) out.features.push_back("emissive");
  if (m.alpha_mode == AlphaMode::Mask) out.features.push_back("alpha_mask");
  if (m.alpha_mode == AlphaMode::Blend) out.features.push_back("alpha_blend");
  if (m.double_sided) out.features.push_back("double_sided");
  if (source) out.extensions = source->extensions;
  return out;
}

std::vector<TextureInfo> textures_of(const std::vector<ModelMaterial>& materials) {
  std::vector<const Texture*> seen;
  std::vector<TextureInfo> out;
  for (const ModelMaterial& m : materials)
    for (const Slot& s : slots(m)) {
      if (!*s.binding) continue;
      const Texture* t = (*s.binding)->texture.get();
      if (std::find(seen.begin(), seen.end(), t) != seen.end()) continue;
      seen.push_back(t);
      out.push_back({t->width(), t->height(), t->memory_bytes(), s.space});
    }
  return out;
}

}  // namespace

ModelInfo describe_model(const Model& model) {
  ModelInfo info;
  info.frame = frame_statement(model.up_axis_unstated);
  describe_extent(model, info);
  info.triangles = int64_t(model.triangle_count());
  info.vertices = int64_t(model.vertex_count());
  info.meshes = model.source.meshes;
  for (size_t i = 0; i < model.materials.size(); ++i)
    info.materials.push_back(material_info(
        model.materials[i], i < model.source.materials.size() ? &model.source.materials[i] : nullptr));
  info.textures = textures_of(model.materials);
  info.cameras = model.source.cameras;
  info.extensions_used = model.source.extensions_used;
  info.warnings = model.source.warnings;
  return info;
}

}  // namespace lp

#pragma once
// A loaded model described: its bounds in the world frame, its counts, its materials and the features
// each uses, its textures, and what its file holds beyond the triangles (ModelSource: cameras,
// extensions, warnings). Computed from the Model as a render uses it, so it describes what renders.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/bounds.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model.hpp"
#include "engine/texture/texture_decode.hpp"

namespace lp {

struct MaterialInfo {
  std::string name;
  // What the material uses, in this order: base_color_texture, metallic_roughness_texture,
  // normal_texture, emissive_texture, emissive (a non-zero emissive factor), alpha_mask or alpha_blend,
  // double_sided (as it renders: an OBJ's materials are).
  std::vector<std::string> features;
  std::vector<std::string> extensions;  // the glTF extensions it carries
};

// A texture the materials use, each once (in the order materials first use it).
struct TextureInfo {
  int width = 0, height = 0;
  int64_t bytes = 0;  // the decoded texels and their mip levels in memory
  ColorSpace color_space = ColorSpace::Linear;
};

struct ModelInfo {
  std::string frame;  // frame_statement (model_frame.hpp)
  // The box of the model's vertices in the world frame (model_frame.hpp; an OBJ's as a scene places
  // it by default, y-up), empty for a model without vertices, and the sphere about the box's centre
  // that holds them all.
  Bounds bounds;
  BoundingSphere sphere;
  int64_t triangles = 0, vertices = 0, meshes = 0;
  std::vector<MaterialInfo> materials;
  std::vector<TextureInfo> textures;
  std::vector<ModelSource::Camera> cameras;  // by index
  std::vector<std::string> extensions_used;
  std::vector<std::string> warnings;
};

ModelInfo describe_model(const Model& model);

}  // namespace lp

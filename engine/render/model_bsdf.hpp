#pragma once
// The BSDF of a model's surface at a hit, made in place: the core metallic-roughness model for a
// material without MaterialLobes (exactly the BSDF such a material always had), glTF's layered model
// (bsdf_gltf_pbr.hpp) for one with them.
#include <optional>

#include "engine/bsdf/bsdf_gltf_pbr.hpp"
#include "engine/bsdf/bsdf_metallic_roughness.hpp"
#include "engine/core/frame.hpp"
#include "engine/render/model_shading.hpp"

namespace lp::render {

class ModelBsdf {
 public:
  // The BSDF for `surface`, valid until the next call.
  const Bsdf& make(const ModelSurface& surface);
  // Places the layers' own normals in the local frame the BSDF is used in (`flipped`: the frame's
  // normal is the surface's turned to face the viewer).
  void orient(const Frame& frame, bool flipped);

 private:
  std::optional<MetallicRoughnessBsdf> core_;
  std::optional<GltfPbrBsdf> layered_;
  Vec3 clearcoat_normal_;  // world
};

GltfPbrParams layered_params(const ModelSurface& surface);

}  // namespace lp::render

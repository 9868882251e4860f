#include "engine/render/model_bsdf.hpp"

namespace lp::render {

GltfPbrParams layered_params(const ModelSurface& surface) {
  const SurfaceLobes& l = *surface.lobes;
  GltfPbrParams p;
  p.base = {surface.base_color, surface.metallic, surface.roughness, l.ior,
            l.specular,         l.specular_color, l.transmission,    l.thin_walled};
  p.clearcoat = l.clearcoat;
  p.clearcoat_roughness = l.clearcoat_roughness;
  p.sheen_color = l.sheen_color;
  p.sheen_roughness = l.sheen_roughness;
  return p;
}

const Bsdf& ModelBsdf::make(const ModelSurface& surface) {
  if (!surface.lobes) return core_.emplace(surface.base_color, surface.metallic, surface.roughness);
  clearcoat_normal_ = surface.lobes->clearcoat_normal;
  return layered_.emplace(layered_params(surface));
}

void ModelBsdf::orient(const Frame& frame, bool flipped) {
  if (layered_)
    layered_->set_clearcoat_normal(frame.to_local(flipped ? -clearcoat_normal_ : clearcoat_normal_));
}

}  // namespace lp::render

#include "engine/render/material_bsdf.hpp"

#include <variant>

#include "engine/bsdf/bsdf_conductor.hpp"
#include "engine/bsdf/bsdf_dielectric.hpp"
#include "engine/bsdf/bsdf_diffuse.hpp"
#include "engine/bsdf/bsdf_mirror.hpp"
#include "engine/bsdf/bsdf_plastic.hpp"
#include "engine/bsdf/bsdf_rough_dielectric.hpp"

namespace lp::render {
namespace {

struct Factory {
  std::unique_ptr<Bsdf> operator()(const DiffuseMaterial& m) const {
    m.validate("material");
    return std::make_unique<DiffuseBsdf>(m.albedo);
  }
  std::unique_ptr<Bsdf> operator()(const MirrorMaterial& m) const {
    m.validate("material");
    return std::make_unique<MirrorBsdf>(m.color);
  }
  std::unique_ptr<Bsdf> operator()(const DielectricMaterial& m) const {
    m.validate("material");
    // Index 1 is no interface, whatever its roughness: the smooth boundary lets the light straight on.
    if (m.roughness < kDeltaLobeAlpha || m.ior == 1) return std::make_unique<DielectricBsdf>(m.ior);
    return std::make_unique<RoughDielectricBsdf>(m.ior, m.roughness);
  }
  std::unique_ptr<Bsdf> operator()(const PlasticMaterial& m) const {
    m.validate("material");
    return std::make_unique<PlasticBsdf>(m.albedo, m.ior, m.roughness);
  }
  std::unique_ptr<Bsdf> operator()(const ConductorMaterial& m) const {
    m.validate("material");
    return std::make_unique<ConductorBsdf>(m.eta, m.k, m.roughness);
  }
};

}  // namespace

std::unique_ptr<Bsdf> make_bsdf(const Material& material) {
  return std::visit(Factory{}, material);
}

}  // namespace lp::render

#include "engine/render/bsdf.hpp"

#include "engine/render/bsdf_conductor.hpp"
#include "engine/render/bsdf_dielectric.hpp"
#include "engine/render/bsdf_diffuse.hpp"
#include "engine/render/bsdf_mirror.hpp"
#include "engine/render/bsdf_plastic.hpp"

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
    return std::make_unique<DielectricBsdf>(m.ior);
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

std::optional<BsdfSample> weighted_sample(const Bsdf& bsdf, Vec3 wo, Vec3 wi) {
  if (wi.z <= 0) return std::nullopt;
  const float p = bsdf.pdf(wo, wi);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{wi, bsdf.eval(wo, wi) / p, p};
}

std::unique_ptr<Bsdf> make_bsdf(const Material& material) {
  return std::visit(Factory{}, material);
}

}  // namespace lp::render

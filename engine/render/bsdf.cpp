#include "engine/render/bsdf.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/bsdf_conductor.hpp"
#include "engine/render/bsdf_dielectric.hpp"
#include "engine/render/bsdf_diffuse.hpp"
#include "engine/render/bsdf_mirror.hpp"
#include "engine/render/bsdf_plastic.hpp"

namespace lp::render {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorKind::InvalidArgument, "material: " + what);
}

bool in_unit(Rgb c) {
  return finite(c) && c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= 1 && c.y <= 1 && c.z <= 1;
}
bool positive(Rgb c) {
  return finite(c) && c.x > 0 && c.y > 0 && c.z > 0;
}
bool non_negative(Rgb c) {
  return finite(c) && c.x >= 0 && c.y >= 0 && c.z >= 0;
}
bool valid_ior(float ior) {
  return std::isfinite(ior) && ior > 0 && ior <= 10;
}
bool valid_roughness(float r) {
  return std::isfinite(r) && r >= 0 && r <= 1;
}

struct Factory {
  std::unique_ptr<Bsdf> operator()(const DiffuseMaterial& m) const {
    require(in_unit(m.albedo), "albedo must be in [0, 1]");
    return std::make_unique<DiffuseBsdf>(m.albedo);
  }
  std::unique_ptr<Bsdf> operator()(const MirrorMaterial& m) const {
    require(in_unit(m.color), "color must be in [0, 1]");
    return std::make_unique<MirrorBsdf>(m.color);
  }
  std::unique_ptr<Bsdf> operator()(const DielectricMaterial& m) const {
    require(valid_ior(m.ior), "ior must be in (0, 10]");
    return std::make_unique<DielectricBsdf>(m.ior);
  }
  std::unique_ptr<Bsdf> operator()(const PlasticMaterial& m) const {
    require(in_unit(m.albedo), "albedo must be in [0, 1]");
    require(valid_ior(m.ior), "ior must be in (0, 10]");
    require(valid_roughness(m.roughness), "roughness must be in [0, 1]");
    return std::make_unique<PlasticBsdf>(m.albedo, m.ior, m.roughness);
  }
  std::unique_ptr<Bsdf> operator()(const ConductorMaterial& m) const {
    require(positive(m.eta), "eta must be > 0");
    require(non_negative(m.k), "k must be >= 0");
    require(valid_roughness(m.roughness), "roughness must be in [0, 1]");
    return std::make_unique<ConductorBsdf>(m.eta, m.k, m.roughness);
  }
};

}  // namespace

std::unique_ptr<Bsdf> make_bsdf(const Material& material) {
  return std::visit(Factory{}, material);
}

}  // namespace lp::render

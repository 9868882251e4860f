#include "engine/bsdf/bsdf.hpp"

namespace lp::render {

std::optional<BsdfSample> weighted_sample(const Bsdf& bsdf, Vec3 wo, Vec3 wi) {
  if (wi.z <= 0) return std::nullopt;
  const float p = bsdf.pdf(wo, wi);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{wi, bsdf.eval(wo, wi) / p, p};
}

}  // namespace lp::render

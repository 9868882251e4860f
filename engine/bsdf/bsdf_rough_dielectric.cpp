#include "engine/bsdf/bsdf_rough_dielectric.hpp"

#include <cmath>

#include "engine/fresnel/dielectric.hpp"

namespace lp::render {
namespace {

// wo's side of the boundary. Every computation runs with wo.z > 0: when wo is inside, both directions
// are negated (the isotropic GGX does not notice) and the indices swap.
struct Side {
  float sign;     // +1: wo outside, -1: inside
  double eta_o;   // index of wo's medium
  double eta_in;  // index of the other one
  float eta() const { return float(eta_in / eta_o); }
};

Side side_of(Vec3 wo, float ior) {
  return wo.z > 0 ? Side{1.0f, 1.0, double(ior)} : Side{-1.0f, double(ior), 1.0};
}

// The microfacet normal that refracts wo (wo.z > 0) into wi (wi.z < 0) for eta = n_i / n_o: the
// generalised half vector, facing up, wo in front of it and wi behind it; nullopt when there is none.
std::optional<Vec3> refracting_normal(Vec3 wo, Vec3 wi, float eta) {
  const Vec3 h = wo + eta * wi;
  const float len2 = dot(h, h);
  if (!(len2 > 0)) return std::nullopt;
  Vec3 m = h / std::sqrt(len2);
  if (m.z < 0) m = -m;
  if (!(m.z > 0) || dot(wo, m) <= 0 || dot(wi, m) >= 0) return std::nullopt;
  return m;
}

// |dm / dwi| of the refraction of wo about m into wi (Walter et al. 2007).
float refraction_jacobian(Vec3 wo, Vec3 wi, Vec3 m, float eta) {
  const float s = dot(wo, m) + eta * dot(wi, m);
  return eta * eta * std::abs(dot(wi, m)) / (s * s);
}

// wo refracted about m by Snell's law, cos_t the cosine of the transmission angle.
Vec3 refract(Vec3 wo, Vec3 m, float eta, float cos_t) {
  return normalize((dot(wo, m) / eta - cos_t) * m - wo / eta);
}

// F of a refraction whose cosines with m are cos_o (wo's side, > 0) and cos_i (< 0), both in the frame
// where wo.z > 0. Taken on the side of the lower index: near the critical angle on the other side,
// F changes faster than float resolves the cosine, and the two directions of a pair would disagree.
float refraction_reflectance(const Side& side, float cos_o, float cos_i) {
  if (side.eta_o <= side.eta_in) return float(fresnel_dielectric(cos_o, side.eta_o, side.eta_in));
  return float(fresnel_dielectric(-cos_i, side.eta_in, side.eta_o));
}

}  // namespace

RoughDielectricBsdf::RoughDielectricBsdf(float ior, float alpha) : ior_(ior), ggx_(alpha) {}

RoughDielectricBsdf::Value RoughDielectricBsdf::evaluate(Vec3 wo, Vec3 wi) const {
  if (wo.z == 0 || wi.z == 0) return {};
  const Side side = side_of(wo, ior_);
  const Vec3 o = side.sign * wo, i = side.sign * wi;
  if (i.z > 0) {
    const Vec3 h = normalize(o + i);
    const float r = float(fresnel_dielectric(dot(o, h), side.eta_o, side.eta_in));
    return {r * ggx_.reflection(o, i, h), r * ggx_.reflection_pdf(o, h)};
  }
  const float eta = side.eta();
  const std::optional<Vec3> m = refracting_normal(o, i, eta);
  if (!m) return {};
  const float cos_o = dot(o, *m), cos_i = dot(i, *m);
  const float t = 1.0f - refraction_reflectance(side, cos_o, cos_i);
  const float s = cos_o + eta * cos_i;
  const float f_cos = t * ggx_.d(*m) * ggx_.g(o, i) * cos_o * -cos_i / (o.z * s * s);
  return {f_cos, t * ggx_.visible_normal_pdf(o, *m) * refraction_jacobian(o, i, *m, eta)};
}

Rgb RoughDielectricBsdf::eval(Vec3 wo, Vec3 wi) const {
  const float f = evaluate(wo, wi).f_cos;
  return {f, f, f};
}

float RoughDielectricBsdf::pdf(Vec3 wo, Vec3 wi) const {
  return evaluate(wo, wi).pdf;
}

std::optional<BsdfSample> RoughDielectricBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z == 0) return std::nullopt;
  const Side side = side_of(wo, ior_);
  const Vec3 o = side.sign * wo;
  const Vec3 m = ggx_.sample_visible_normal(o, u.x, u.y);
  const float cos_o = dot(o, m);
  if (!(cos_o > 0)) return std::nullopt;
  // Under total internal reflection the reflectance is 1: always a reflection.
  const DielectricFresnel fresnel = fresnel_dielectric_polarized(cos_o, side.eta_o, side.eta_in);
  const float r = float(fresnel.reflectance());
  Vec3 i;
  float eta = 1, p;
  if (u_lobe < r) {
    i = reflect(o, m);
    if (i.z <= 0) return std::nullopt;
    p = r * ggx_.reflection_pdf(o, m);
  } else {
    eta = side.eta();
    i = refract(o, m, eta, float(fresnel.cos_t));
    if (i.z >= 0) return std::nullopt;
    p = (1.0f - r) * ggx_.visible_normal_pdf(o, m) * refraction_jacobian(o, i, m, eta);
  }
  const float weight = ggx_.g(o, i) / (ggx_.g1(o) * eta * eta);
  return BsdfSample{side.sign * i, {weight, weight, weight}, p, eta, false};
}

std::optional<Vec3> RoughDielectricBsdf::sample_refraction(Vec3 wo, Point2 u) const {
  if (!(wo.z > 0)) return std::nullopt;
  const Vec3 m = ggx_.sample_visible_normal(wo, u.x, u.y);
  const float cos_o = dot(wo, m);
  if (!(cos_o > 0)) return std::nullopt;
  const std::optional<double> cos_t = transmitted_cos(cos_o, 1.0, ior_);
  if (!cos_t) return std::nullopt;
  const Vec3 wi = refract(wo, m, ior_, float(*cos_t));
  if (wi.z >= 0) return std::nullopt;
  return wi;
}

float RoughDielectricBsdf::refraction_pdf(Vec3 wo, Vec3 wi) const {
  if (!(wo.z > 0) || !(wi.z < 0)) return 0;
  const std::optional<Vec3> m = refracting_normal(wo, wi, ior_);
  if (!m) return 0;
  return ggx_.visible_normal_pdf(wo, *m) * refraction_jacobian(wo, wi, *m, ior_);
}

}  // namespace lp::render

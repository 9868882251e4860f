// The rough dielectric boundary (bsdf_rough_dielectric.hpp), from outside and from inside: sampling
// against its pdf over the whole sphere (chi-square), sample weights against eval / pdf, energy,
// generalised reciprocity of the refraction, and the smooth limit's Fresnel reflectance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/bsdf/bsdf_rough_dielectric.hpp"
#include "engine/core/constants.hpp"
#include "engine/core/rng.hpp"
#include "support/sphere_chi_square.hpp"

namespace lp::render {
namespace {

// The boundary's index and the side wo lies on.
struct View {
  std::string name;
  float ior;
  bool inside;  // wo.z < 0: the path leaves the medium, relative index 1 / ior
};

const View kViews[] = {
    {"ior 1.5", 1.5f, false}, {"ior 1.33", 1.33f, false}, {"ior 1/1.5 inside", 1.5f, true}};
const float kAlphas[] = {0.05f, 0.3f, 0.8f};
const float kThetas[] = {0.0f, 40.0f, 75.0f};

Vec3 direction(float theta_deg, float phi) {
  const float t = theta_deg * kPiF / 180.0f;
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

Vec3 below(Vec3 w) {
  return {w.x, w.y, -w.z};
}

Vec3 view_direction(const View& v, float theta_deg) {
  const Vec3 w = direction(theta_deg, 0.7f);
  return v.inside ? below(w) : w;
}

// Index of the medium on w's side.
float index_at(Vec3 w, float ior) {
  return w.z > 0 ? 1.0f : ior;
}

std::string label(const View& v, float alpha, float theta) {
  char text[96];
  std::snprintf(text, sizeof text, "%s alpha %.2f theta %.0f", v.name.c_str(), double(alpha), double(theta));
  return text;
}

// Every case: each view, roughness and angle of wo.
void for_each_case(const std::function<void(const View&, float alpha, float theta)>& check) {
  for (const View& v : kViews)
    for (float alpha : kAlphas)
      for (float theta : kThetas) check(v, alpha, theta);
}

std::optional<BsdfSample> draw(const Bsdf& bsdf, Vec3 wo, Rng& rng) {
  const float u_lobe = rng.uniform_float();
  return bsdf.sample(wo, u_lobe, {rng.uniform_float(), rng.uniform_float()});
}

constexpr int kChiSquareSamples = 200000;

TEST(RenderRoughDielectric, SamplingMatchesPdfChiSquare) {
  for_each_case([](const View& v, float alpha, float theta) {
    const RoughDielectricBsdf bsdf(v.ior, alpha);
    const Vec3 wo = view_direction(v, theta);
    const auto r = test::sphere_chi_square(
        [&](Rng& rng) -> std::optional<Vec3> {
          const auto s = draw(bsdf, wo, rng);
          return s ? std::optional<Vec3>(s->wi) : std::nullopt;
        },
        [&](Vec3 wi) { return bsdf.pdf(wo, wi); }, kChiSquareSamples, uint64_t(theta * 10 + alpha * 1000));
    std::printf("%s: %s\n", label(v, alpha, theta).c_str(), r.summary().c_str());
    EXPECT_GT(r.p_value, 0.01) << label(v, alpha, theta) << ": " << r.summary();
  });
}

TEST(RenderRoughDielectric, RefractionLobeSamplingMatchesItsPdfChiSquare) {
  for_each_case([](const View& v, float alpha, float theta) {
    if (v.inside) return;  // the lobe refracts from the outside in
    const RoughDielectricBsdf bsdf(v.ior, alpha);
    const Vec3 wo = view_direction(v, theta);
    const auto r = test::sphere_chi_square(
        [&](Rng& rng) {
          return bsdf.sample_refraction(wo, {rng.uniform_float(), rng.uniform_float()});
        },
        [&](Vec3 wi) { return bsdf.refraction_pdf(wo, wi); }, kChiSquareSamples,
        uint64_t(theta * 10 + alpha * 1000));
    std::printf("refraction lobe, %s: %s\n", label(v, alpha, theta).c_str(), r.summary().c_str());
    EXPECT_GT(r.p_value, 0.01) << "refraction lobe, " << label(v, alpha, theta) << ": " << r.summary();
  });
}

TEST(RenderRoughDielectric, SampleWeightIsEvalOverPdf) {
  for_each_case([](const View& v, float alpha, float theta) {
    const RoughDielectricBsdf bsdf(v.ior, alpha);
    const Vec3 wo = view_direction(v, theta);
    const float eta_crossing = v.inside ? 1.0f / v.ior : v.ior;
    Rng rng(7, uint64_t(theta));
    int refracted = 0;
    for (int n = 0; n < 4000; ++n) {
      const auto s = draw(bsdf, wo, rng);
      if (!s) continue;
      ASSERT_FALSE(s->delta);
      const bool crosses = s->wi.z * wo.z < 0;
      refracted += crosses;
      ASSERT_EQ(s->eta, crosses ? eta_crossing : 1.0f) << label(v, alpha, theta);
      const float pdf = bsdf.pdf(wo, s->wi);
      ASSERT_NEAR(s->pdf, pdf, 2e-3f * pdf) << label(v, alpha, theta);
      const float expected = bsdf.eval(wo, s->wi).x / pdf;
      ASSERT_NEAR(s->weight.x, expected, 2e-3f * expected + 1e-6f) << label(v, alpha, theta);
    }
    if (!(v.inside && theta > 45)) {  // past the critical angle most of it is reflected
      EXPECT_GT(refracted, 1000) << label(v, alpha, theta);
    }
  });
}

// Weights times eta^2 undo the radiance scaling of a refraction: what is left is the energy carried.
TEST(RenderRoughDielectric, EnergyAtMostOneAndAlmostOneWhenSmooth) {
  for_each_case([](const View& v, float alpha, float theta) {
    constexpr int kSamples = 100000;
    const RoughDielectricBsdf bsdf(v.ior, alpha);
    const Vec3 wo = view_direction(v, theta);
    Rng rng(11, uint64_t(theta));
    double energy = 0;
    for (int n = 0; n < kSamples; ++n)
      if (const auto s = draw(bsdf, wo, rng)) energy += double(s->weight.x * s->eta * s->eta);
    energy /= kSamples;
    std::printf("%s: energy %.5f\n", label(v, alpha, theta).c_str(), energy);
    EXPECT_LE(energy, 1.0 + 5e-3) << label(v, alpha, theta);
    if (alpha == 0.05f && theta == 0.0f) {
      EXPECT_GE(energy, 0.97) << label(v, alpha, theta);
    }
  });
}

// With f = eval / |cos wi| and radiance scaled by 1 / eta^2 on crossing, a refraction from wo (medium of
// index n_o) to wi (index n_i) obeys f(wo, wi) / n_o^2 == f(wi, wo) / n_i^2 (Veach 1997, chapter 5);
// a reflection, f(wo, wi) == f(wi, wo).
TEST(RenderRoughDielectric, GeneralisedReciprocity) {
  for (float ior : {1.5f, 1.33f})
    for (float alpha : kAlphas) {
      const RoughDielectricBsdf bsdf(ior, alpha);
      const auto f = [&](Vec3 wo, Vec3 wi) { return bsdf.eval(wo, wi).x / std::abs(wi.z); };
      Rng rng(3, uint64_t(alpha * 100));
      int refracting_pairs = 0;
      for (int n = 0; n < 4000; ++n) {
        const Vec3 a = direction(89.0f * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
        const Vec3 b = direction(89.0f * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
        // In turn: a reflection outside, a refraction, a reflection inside.
        const int kind = n % 3;
        const bool crossing = kind == 1;
        const Vec3 wo = kind == 2 ? below(a) : a;
        const Vec3 wi = kind == 0 ? b : below(b);
        const float n_o = index_at(wo, ior), n_i = index_at(wi, ior);
        const float forward = f(wo, wi) / (n_o * n_o), backward = f(wi, wo) / (n_i * n_i);
        refracting_pairs += crossing && forward > 0;
        ASSERT_NEAR(forward, backward, 1e-3f * std::max(forward, backward) + 1e-7f)
            << "ior " << ior << " alpha " << alpha << " wo.z " << wo.z << " wi.z " << wi.z;
      }
      EXPECT_GT(refracting_pairs, 300) << "ior " << ior << " alpha " << alpha;
    }
}

// Nearly smooth, at normal incidence: the reflected fraction is Fresnel's ((ior - 1) / (ior + 1))^2 from
// either side, and the rest is refracted.
TEST(RenderRoughDielectric, NearlySmoothReflectsFresnelAtNormalIncidence) {
  constexpr int kSamples = 200000;
  for (const View& v : kViews) {
    const RoughDielectricBsdf bsdf(v.ior, kDeltaLobeAlpha);
    const Vec3 wo{0, 0, v.inside ? -1.0f : 1.0f};
    Rng rng(5, 1);
    double reflected = 0, refracted = 0;
    for (int n = 0; n < kSamples; ++n) {
      const float u_lobe = (float(n) + rng.uniform_float()) / kSamples;
      const auto s = bsdf.sample(wo, u_lobe, {rng.uniform_float(), rng.uniform_float()});
      if (!s) continue;
      const double throughput = double(bsdf.eval(wo, s->wi).x / bsdf.pdf(wo, s->wi));
      if (s->wi.z * wo.z > 0)
        reflected += throughput;
      else
        refracted += throughput * double(s->eta * s->eta);
    }
    reflected /= kSamples;
    refracted /= kSamples;
    const double fresnel = std::pow((v.ior - 1.0) / (v.ior + 1.0), 2);
    std::printf("%s: reflected %.5f (Fresnel %.5f), refracted %.5f\n", v.name.c_str(), reflected, fresnel,
                refracted);
    EXPECT_NEAR(reflected, fresnel, 1e-3) << v.name;
    EXPECT_NEAR(refracted, 1 - fresnel, 1e-3) << v.name;
  }
}

}  // namespace
}  // namespace lp::render

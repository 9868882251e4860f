// BSDFs of the path tracer: sampling agrees with the pdf (chi-square), sample weights agree with
// eval / pdf, reciprocity, energy conservation, and analytic albedos.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/bsdf/bsdf_gltf_pbr.hpp"
#include "engine/bsdf/bsdf_metallic_roughness.hpp"
#include "engine/bsdf/bsdf_plastic.hpp"
#include "engine/bsdf/bsdf_rough_dielectric.hpp"
#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/fresnel/conductor.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/fresnel/metals.hpp"
#include "engine/render/material_bsdf.hpp"
#include "support/sphere_chi_square.hpp"

namespace lp::render {
namespace {

Vec3 direction(float theta_deg, float phi) {
  const float t = theta_deg * kPiF / 180.0f;
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

ConductorMaterial gold(float roughness) {
  const auto& m = lookup_metal("gold");
  return {m.eta_rgb(), m.k_rgb(), roughness};
}

// A conductor with F > 0.9999 at every angle.
ConductorMaterial white_metal(float roughness) {
  return {{0.001f, 0.001f, 0.001f}, {20, 20, 20}, roughness};
}

struct Case {
  std::string name;
  std::shared_ptr<const Bsdf> bsdf;
};

std::shared_ptr<const Bsdf> model_bsdf(Rgb base, float metallic, float roughness) {
  return std::make_shared<MetallicRoughnessBsdf>(base, metallic, roughness);
}

// glTF's material with its extensions' lobes (bsdf_gltf_pbr.hpp).
GltfPbrParams gltf(Rgb base, float metallic, float roughness) {
  GltfPbrParams p;
  p.base.base_color = base;
  p.base.metallic = metallic;
  p.base.roughness = roughness;
  return p;
}

GltfPbrParams with_clearcoat(GltfPbrParams p, float weight, float roughness) {
  p.clearcoat = weight;
  p.clearcoat_roughness = roughness;
  return p;
}

GltfPbrParams with_sheen(GltfPbrParams p, Rgb color, float roughness) {
  p.sheen_color = color;
  p.sheen_roughness = roughness;
  return p;
}

GltfPbrParams with_specular(GltfPbrParams p, float ior, float specular, Rgb color) {
  p.base.ior = ior;
  p.base.specular = specular;
  p.base.specular_color = color;
  return p;
}

GltfPbrParams with_transmission(GltfPbrParams p, float transmission, bool thin_walled) {
  p.base.transmission = transmission;
  p.base.thin_walled = thin_walled;
  return p;
}

std::shared_ptr<const Bsdf> gltf_bsdf(const GltfPbrParams& p) {
  return std::make_shared<GltfPbrBsdf>(p);
}

// Reflecting glTF lobes, reciprocal (the clearcoat about the shading normal).
std::vector<Case> gltf_reflection_cases() {
  const Rgb base{0.6f, 0.3f, 0.2f};
  return {
      {"gltf_clearcoat_r0.2", gltf_bsdf(with_clearcoat(gltf(base, 0, 0.6f), 1, 0.2f))},
      {"gltf_clearcoat_half_metal", gltf_bsdf(with_clearcoat(gltf(base, 1, 0.3f), 0.5f, 0.6f))},
      {"gltf_sheen_r0.3", gltf_bsdf(with_sheen(gltf(base, 0, 0.8f), {0.9f, 0.7f, 0.5f}, 0.3f))},
      {"gltf_sheen_r1", gltf_bsdf(with_sheen(gltf(base, 0.5f, 0.4f), {1, 1, 1}, 1))},
      {"gltf_ior_1.33", gltf_bsdf(with_specular(gltf(base, 0, 0.5f), 1.33f, 1, {1, 1, 1}))},
      {"gltf_specular_color", gltf_bsdf(with_specular(gltf(base, 0.3f, 0.3f), 1.7f, 0.7f, {1, 0.4f, 0.2f}))},
      {"gltf_all_layers",
       gltf_bsdf(with_sheen(
           with_clearcoat(with_specular(gltf(base, 0.2f, 0.7f), 2, 0.8f, {0.5f, 1, 1}), 0.7f, 0.4f),
           {0.3f, 0.6f, 0.9f}, 0.5f))},
  };
}

// BSDFs with a non-delta part (the ones light sampling and the chi-square test apply to).
std::vector<Case> non_delta_cases() {
  return {
      {"diffuse", make_bsdf(DiffuseMaterial{{0.8f, 0.5f, 0.2f}})},
      {"conductor_a0.1", make_bsdf(gold(0.1f))},
      {"conductor_a0.3", make_bsdf(gold(0.3f))},
      {"conductor_a0.7", make_bsdf(gold(0.7f))},
      {"white_conductor_a1", make_bsdf(white_metal(1.0f))},
      {"plastic_a0.1", make_bsdf(PlasticMaterial{{0.7f, 0.1f, 0.1f}, 1.5f, 0.1f})},
      {"plastic_a0.4", make_bsdf(PlasticMaterial{{0.2f, 0.6f, 0.9f}, 1.5f, 0.4f})},
      {"plastic_a1", make_bsdf(PlasticMaterial{{0.9f, 0.9f, 0.9f}, 2.0f, 1.0f})},
      {"plastic_smooth", make_bsdf(PlasticMaterial{{0.5f, 0.5f, 0.5f}, 1.5f, 0.0f})},
      {"model_metal_r0.5", model_bsdf({0.9f, 0.6f, 0.3f}, 1.0f, 0.5f)},
      {"model_dielectric_r0.7", model_bsdf({0.2f, 0.5f, 0.8f}, 0.0f, 0.7f)},
      {"model_mixed_r1", model_bsdf({0.7f, 0.7f, 0.2f}, 0.4f, 1.0f)},
      {"model_mixed_r0", model_bsdf({0.7f, 0.7f, 0.2f}, 0.4f, 0.0f)},
  };
}

// Every glTF lobe set sampled and evaluated: the reflecting ones, a clearcoat about a tilted normal and
// rough thin-walled transmission (neither reciprocal in the sense the reciprocity test checks).
std::vector<Case> gltf_non_delta_cases() {
  std::vector<Case> cases = gltf_reflection_cases();
  GltfPbrParams tilted = with_clearcoat(gltf({0.5f, 0.5f, 0.5f}, 0, 0.5f), 1, 0.3f);
  tilted.clearcoat_normal = normalize(Vec3{0.3f, -0.2f, 0.9f});
  cases.push_back({"gltf_clearcoat_tilted", gltf_bsdf(tilted)});
  cases.push_back({"gltf_thin_transmission_r0.4",
                   gltf_bsdf(with_transmission(gltf({0.9f, 0.8f, 0.6f}, 0, 0.4f), 0.8f, true))});
  cases.push_back(
      {"gltf_thin_transmission_coated",
       gltf_bsdf(with_clearcoat(with_transmission(gltf({1, 1, 1}, 0.1f, 0.7f), 1, true), 1, 0.4f))});
  cases.push_back(
      {"gltf_clearcoat_r0", gltf_bsdf(with_clearcoat(gltf({0.4f, 0.5f, 0.6f}, 0.3f, 0.6f), 1, 0))});
  cases.push_back(
      {"gltf_ior_1.33_r0", gltf_bsdf(with_specular(gltf({0.6f, 0.3f, 0.2f}, 0.5f, 0), 1.33f, 1, {1, 1, 1}))});
  cases.push_back({"gltf_thin_transmission_r0",
                   gltf_bsdf(with_transmission(gltf({0.9f, 0.8f, 0.6f}, 0, 0), 0.5f, true))});
  cases.push_back({"gltf_thick_transmission_coated_r0.6",
                   gltf_bsdf(with_clearcoat(with_transmission(gltf({0.9f, 0.9f, 0.9f}, 0.2f, 0.6f), 1, false),
                                            1, 0.3f))});
  cases.push_back({"gltf_thick_transmission_r0.3",
                   gltf_bsdf(with_transmission(gltf({0.9f, 0.9f, 0.9f}, 0, 0.3f), 0.6f, false))});
  return cases;
}

const float kThetas[] = {10.0f, 55.0f, 82.0f};

// Delta lobes and failed samples fall in the chi-square's last cell, which expects the mass the pdf
// lacks.
void expect_sampling_matches_pdf(const std::vector<Case>& cases) {
  constexpr int kSamples = 250000;
  for (const Case& c : cases) {
    const Bsdf* bsdf = c.bsdf.get();
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta, 0.7f);
      const auto r = test::sphere_chi_square(
          [&](Rng& rng) -> std::optional<Vec3> {
            const float u_lobe = rng.uniform_float();
            const Point2 u{rng.uniform_float(), rng.uniform_float()};
            const auto s = bsdf->sample(wo, u_lobe, u);
            return s && !s->delta ? std::optional<Vec3>(s->wi) : std::nullopt;
          },
          [&](Vec3 wi) { return bsdf->pdf(wo, wi); }, kSamples, uint64_t(theta * 100) + 1);
      std::printf("%s theta %.0f: %s\n", c.name.c_str(), double(theta), r.summary().c_str());
      EXPECT_GT(r.p_value, 0.01) << c.name << " theta " << theta << ": " << r.summary();
    }
  }
}

TEST(RenderBsdf, SamplingMatchesPdfChiSquare) {
  expect_sampling_matches_pdf(non_delta_cases());
}

TEST(RenderBsdf, GltfLobesSamplingMatchesPdfChiSquare) {
  expect_sampling_matches_pdf(gltf_non_delta_cases());
}

TEST(RenderBsdf, SampleWeightIsEvalOverPdf) {
  std::vector<Case> cases = non_delta_cases();
  for (Case& c : gltf_non_delta_cases()) cases.push_back(std::move(c));
  for (const Case& c : cases) {
    const Bsdf* bsdf = c.bsdf.get();
    Rng rng(7, 1);
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta, 2.0f);
      for (int i = 0; i < 2000; ++i) {
        const auto s = bsdf->sample(wo, rng.uniform_float(), {rng.uniform_float(), rng.uniform_float()});
        if (!s || s->delta) continue;
        const float pdf = bsdf->pdf(wo, s->wi);
        ASSERT_NEAR(s->pdf, pdf, 2e-3f * pdf) << c.name;
        const Rgb expected = bsdf->eval(wo, s->wi) / pdf;
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(s->weight[k], expected[k], 2e-3f * expected[k] + 1e-6f) << c.name;
      }
    }
  }
}

TEST(RenderBsdf, Reciprocity) {
  std::vector<Case> cases = non_delta_cases();
  for (Case& c : gltf_reflection_cases()) cases.push_back(std::move(c));
  for (const Case& c : cases) {
    const Bsdf* bsdf = c.bsdf.get();
    Rng rng(3, 9);
    for (int i = 0; i < 1000; ++i) {
      const Vec3 a = direction(89.0f * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
      const Vec3 b = direction(89.0f * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
      const Rgb fab = bsdf->eval(a, b) / b.z, fba = bsdf->eval(b, a) / a.z;
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(fab[k], fba[k], 1e-4f * std::max(1.0f, fab[k])) << c.name;
    }
  }
}

// Directional albedo: the mean sample weight (times eta^2 for a refraction, undoing the radiance
// scaling) is the fraction of energy scattered, which must not exceed 1.
double albedo(const Bsdf& bsdf, Vec3 wo, int channel, int n) {
  Rng rng(11, uint64_t(wo.z * 1e6f));
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf.sample(wo, rng.uniform_float(), {rng.uniform_float(), rng.uniform_float()});
    if (s) sum += double(s->weight[channel]) * s->eta * s->eta;
  }
  return sum / n;
}

TEST(RenderBsdf, EnergyAtMostOne) {
  // White versions of every material: albedo 1, a perfect mirror, a conductor with k large.
  const std::vector<Case> cases = {
      {"diffuse", make_bsdf(DiffuseMaterial{{1, 1, 1}})},
      {"mirror", make_bsdf(MirrorMaterial{{1, 1, 1}})},
      {"dielectric", make_bsdf(DielectricMaterial{1.5f})},
      {"plastic_smooth", make_bsdf(PlasticMaterial{{1, 1, 1}, 1.5f, 0})},
      {"plastic_a0.1", make_bsdf(PlasticMaterial{{1, 1, 1}, 1.5f, 0.1f})},
      {"plastic_a0.5", make_bsdf(PlasticMaterial{{1, 1, 1}, 1.5f, 0.5f})},
      {"plastic_a1", make_bsdf(PlasticMaterial{{1, 1, 1}, 1.5f, 1.0f})},
      {"conductor_a0.05", make_bsdf(gold(0.05f))},
      {"conductor_a0.5", make_bsdf(gold(0.5f))},
      {"conductor_a1", make_bsdf(ConductorMaterial{{0.05f, 0.05f, 0.05f}, {8, 8, 8}, 1.0f})},
      {"white_conductor_a0.02", make_bsdf(white_metal(0.02f))},
      {"white_conductor_a1", make_bsdf(white_metal(1.0f))},
      {"model_metal_r0.3", model_bsdf({1, 1, 1}, 1, 0.3f)},
      {"model_dielectric_r1", model_bsdf({1, 1, 1}, 0, 1)},
      {"gltf_clearcoat_r0", gltf_bsdf(with_clearcoat(gltf({1, 1, 1}, 0, 0.3f), 1, 0))},
      {"gltf_clearcoat_r1_metal", gltf_bsdf(with_clearcoat(gltf({1, 1, 1}, 1, 0.1f), 1, 1))},
      {"gltf_sheen_r0", gltf_bsdf(with_sheen(gltf({1, 1, 1}, 0, 0.5f), {1, 1, 1}, 0))},
      {"gltf_sheen_r0.5", gltf_bsdf(with_sheen(gltf({1, 1, 1}, 1, 0.5f), {1, 1, 1}, 0.5f))},
      {"gltf_sheen_r1", gltf_bsdf(with_sheen(gltf({1, 1, 1}, 0, 1), {1, 1, 1}, 1))},
      {"gltf_specular_f90", gltf_bsdf(with_specular(gltf({1, 1, 1}, 0, 0.4f), 3, 1, {2, 2, 2}))},
      {"gltf_all_layers",
       gltf_bsdf(with_sheen(with_clearcoat(with_transmission(gltf({1, 1, 1}, 0, 0.6f), 0.5f, true), 1, 0.2f),
                            {1, 1, 1}, 0.7f))},
      {"gltf_thick_coated",
       gltf_bsdf(with_clearcoat(with_transmission(gltf({1, 1, 1}, 0, 0.6f), 1, false), 1, 0.2f))},
  };
  for (const Case& c : cases) {
    for (float theta : {0.0f, 30.0f, 60.0f, 80.0f, 88.0f}) {
      const double e = albedo(*c.bsdf, direction(theta, 0.4f), 0, 100000);
      EXPECT_LE(e, 1.0 + 5e-3) << c.name << " theta " << theta;
    }
  }
}

TEST(RenderBsdf, CompensatedWhiteLobesReflectEverything) {
  // F = 1 (or a white base under the coat): single scattering plus its compensation reflect all the
  // light, to the accuracy of the albedo tables (microfacet_albedo.hpp; 3e-3 for mu > 0.05) and the
  // noise of 200000 samples.
  const std::vector<Case> cases = {
      {"white_conductor_a0.1", make_bsdf(white_metal(0.1f))},
      {"white_conductor_a0.5", make_bsdf(white_metal(0.5f))},
      {"white_conductor_a1", make_bsdf(white_metal(1.0f))},
      {"plastic_a0.3", make_bsdf(PlasticMaterial{{1, 1, 1}, 1.5f, 0.3f})},
      {"plastic_a1_ior3", make_bsdf(PlasticMaterial{{1, 1, 1}, 3.0f, 1.0f})},
      {"model_metal_r0.1", model_bsdf({1, 1, 1}, 1, 0.1f)},
      {"model_metal_r1", model_bsdf({1, 1, 1}, 1, 1)},
      {"model_dielectric_r0.5", model_bsdf({1, 1, 1}, 0, 0.5f)},
      {"model_mixed_r0.8", model_bsdf({1, 1, 1}, 0.5f, 0.8f)},
      {"model_metal_r0", model_bsdf({1, 1, 1}, 1, 0)},
      {"model_dielectric_r0", model_bsdf({1, 1, 1}, 0, 0)},
      {"model_mixed_r0", model_bsdf({1, 1, 1}, 0.5f, 0)},
  };
  for (const Case& c : cases)
    for (float theta : {0.0f, 45.0f, 70.0f, 85.0f}) {
      const double e = albedo(*c.bsdf, direction(theta, 0.4f), 1, 200000);
      EXPECT_NEAR(e, 1.0, 5e-3) << c.name << " theta " << theta;
    }
}

TEST(RenderBsdf, GltfBasesWithoutLayersConserveEnergy) {
  // A white base of any ior and a white specular colour reflects E_s(mu_o) and passes the rest to a
  // diffuse lobe and a transmission of albedo 1 (reflection + transmission, eta^2 undone): 1 to the
  // accuracy of the albedo tables and the noise of 200000 samples, as CompensatedWhiteLobesReflectEverything.
  const Rgb white{1, 1, 1};
  const std::vector<Case> cases = {
      {"ior_1.33_r0.5", gltf_bsdf(with_specular(gltf(white, 0, 0.5f), 1.33f, 1, white))},
      {"ior_2.5_r0.1", gltf_bsdf(with_specular(gltf(white, 0, 0.1f), 2.5f, 1, white))},
      {"specular_0.5_r1", gltf_bsdf(with_specular(gltf(white, 0, 1), 1.5f, 0.5f, white))},
      {"ior_1.33_r0", gltf_bsdf(with_specular(gltf(white, 0, 0), 1.33f, 1, white))},
      {"specular_0.5_r0", gltf_bsdf(with_specular(gltf(white, 0, 0), 1.5f, 0.5f, white))},
      {"half_metal_ior_1.33_r0", gltf_bsdf(with_specular(gltf(white, 0.5f, 0), 1.33f, 1, white))},
      {"thin_smooth", gltf_bsdf(with_transmission(gltf(white, 0, 0), 1, true))},
      {"thin_half_smooth", gltf_bsdf(with_transmission(gltf(white, 0, 0), 0.5f, true))},
      {"thin_r0.5", gltf_bsdf(with_transmission(gltf(white, 0, 0.5f), 1, true))},
      {"thin_half_r0.8", gltf_bsdf(with_transmission(gltf(white, 0, 0.8f), 0.5f, true))},
      {"thick_r0.3", gltf_bsdf(with_transmission(gltf(white, 0, 0.3f), 1, false))},
      {"thick_ior_1", gltf_bsdf(with_transmission(with_specular(gltf(white, 0, 0), 1, 1, white), 1, false))},
  };
  for (const Case& c : cases)
    for (float theta : {0.0f, 45.0f, 70.0f, 85.0f}) {
      const double e = albedo(*c.bsdf, direction(theta, 0.4f), 1, 200000);
      EXPECT_NEAR(e, 1.0, 5e-3) << c.name << " theta " << theta;
    }
}

TEST(RenderBsdf, RoughnessZeroIsAMirror) {
  // A polished metal, a smooth plastic's coat, glTF's smooth specular layer and its default clear coat
  // (roughness 0) reflect as mirrors: every such sample goes to wo mirrored, carrying the lobe's Fresnel
  // factor F(wo.n) (weight times the probability of the lobe), so a small bright source keeps its radiance.
  const Rgb base{0.9f, 0.6f, 0.3f};
  const auto schlick = [](Rgb f0, float mu) { return f0 + (Rgb{1, 1, 1} - f0) * std::pow(1.0f - mu, 5.0f); };
  const auto coat_f = [](float mu) { return float(fresnel_dielectric(mu, 1.0, kModelDielectricIor)); };
  struct Mirror {
    std::string name;
    std::shared_ptr<const Bsdf> bsdf;
    float u_lobe;  // chooses the mirror lobe
    std::function<Rgb(float mu)> reflectance;
  };
  const std::vector<Mirror> mirrors = {
      {"model_metal", model_bsdf(base, 1, 0), 0.5f, [&](float mu) { return schlick(base, mu); }},
      {"model_half_metal", model_bsdf(base, 0.5f, 0.02f), 0.25f,
       [&](float mu) { return schlick(base, mu) * 0.5f; }},
      {"gltf_specular", gltf_bsdf(with_specular(gltf({0, 0, 0}, 0, 0), 1.33f, 1, {1, 1, 1})), 0.5f,
       [&](float mu) {
         const float f0 = (0.33f / 2.33f) * (0.33f / 2.33f);
         return schlick({f0, f0, f0}, mu);
       }},
      {"gltf_clearcoat", gltf_bsdf(with_clearcoat(gltf(base, 0, 0.5f), 1, 0)), 0.0f,
       [&](float mu) {
         return Rgb{coat_f(mu), coat_f(mu), coat_f(mu)};
       }},
  };
  for (const Mirror& m : mirrors) {
    EXPECT_EQ(m.bsdf->has_non_delta_lobe(), m.name != "model_metal") << m.name;
    for (float theta : {0.0f, 40.0f, 75.0f}) {
      const Vec3 wo = direction(theta, 1.1f);
      const auto s = m.bsdf->sample(wo, m.u_lobe, {0.3f, 0.8f});
      ASSERT_TRUE(s && s->delta) << m.name << " theta " << theta;
      EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f) << m.name;
      EXPECT_NEAR(s->wi.y, -wo.y, 1e-6f) << m.name;
      EXPECT_NEAR(s->wi.z, wo.z, 1e-6f) << m.name;
      const Rgb expected = m.reflectance(wo.z);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(s->weight[k] * s->pdf, expected[k], 1e-5f) << m.name << " theta " << theta;
      if (!m.bsdf->has_non_delta_lobe()) {
        EXPECT_EQ(m.bsdf->eval(wo, s->wi), (Rgb{})) << m.name;
      }
    }
  }
}

TEST(RenderBsdf, GltfRoughThickSurfaceIsARoughInterfaceFromInside) {
  // Seen from inside its volume, a rough transmitting surface of roughness r is the rough dielectric
  // interface of its index and alpha r^2: it reflects and refracts back out through the same microfacets.
  const float roughness = 0.5f, ior = 1.5f;
  const auto gltf_surface = gltf_bsdf(with_transmission(gltf({1, 1, 1}, 0, roughness), 1, false));
  const RoughDielectricBsdf interface(ior, roughness * roughness);
  Rng rng(5, 2);
  for (int i = 0; i < 200; ++i) {
    const Vec3 wo = direction(100 + 75 * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
    const Vec3 wi = direction(175 * rng.uniform_float(), 2 * kPiF * rng.uniform_float());
    EXPECT_EQ(gltf_surface->eval(wo, wi), interface.eval(wo, wi));
    EXPECT_EQ(gltf_surface->pdf(wo, wi), interface.pdf(wo, wi));
  }
  EXPECT_TRUE(gltf_surface->has_non_delta_lobe());
  EXPECT_FALSE(gltf_surface->two_sided());
}

TEST(RenderBsdf, GltfClearTransmissionIsIndexMatchedAtIorOne) {
  // ior 1: F0 = 0; a smooth thin wall lets the light straight through, a thick one does not bend it.
  for (bool thin : {true, false}) {
    const auto b =
        gltf_bsdf(with_transmission(with_specular(gltf({1, 1, 1}, 0, 0), 1, 1, {1, 1, 1}), 1, thin));
    const Vec3 wo = direction(20, 0.3f);
    const auto s = b->sample(wo, 0.999f, {0.5f, 0.5f});
    ASSERT_TRUE(s && s->delta);
    EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
    EXPECT_NEAR(s->wi.z, -wo.z, 1e-6f);
    EXPECT_NEAR(s->weight.x * s->pdf, 1.0f, 1e-4f);
  }
}

TEST(RenderBsdf, AnalyticAlbedos) {
  constexpr int kN = 200000;
  for (float theta : {0.0f, 45.0f, 75.0f}) {
    const Vec3 wo = direction(theta, 1.0f);
    const double fresnel = fresnel_dielectric(wo.z, 1.0, 1.5);
    // Lambert: exactly the albedo (every weight is the albedo).
    EXPECT_NEAR(albedo(*make_bsdf(DiffuseMaterial{{0.3f, 0.6f, 0.9f}}), wo, 1, kN), 0.6, 1e-6);
    // Glass: reflection + transmission = 1, and the reflected fraction is F.
    const auto glass = make_bsdf(DielectricMaterial{1.5f});
    EXPECT_NEAR(albedo(*glass, wo, 0, kN), 1.0, 1e-5);
    // Smooth plastic: F + (1 - F) albedo.
    EXPECT_NEAR(albedo(*make_bsdf(PlasticMaterial{{0.5f, 0.5f, 0.5f}, 1.5f, 0}), wo, 0, kN),
                fresnel + (1 - fresnel) * 0.5, 5e-3);
    // Smooth gold: the conductor Fresnel reflectance per channel.
    const auto g = gold(0);
    const Rgb f = fresnel_conductor(wo.z, g.eta, g.k);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(albedo(*make_bsdf(g), wo, k, 1000), f[k], 1e-6);
  }
}

TEST(RenderBsdf, DielectricReflectsFresnelFractionAndRefractsBySnell) {
  const auto glass = make_bsdf(DielectricMaterial{1.5f});
  for (float theta : {20.0f, 60.0f}) {
    for (bool inside : {false, true}) {
      Vec3 wo = direction(theta, 0.3f);
      if (inside) wo.z = -wo.z;
      const double eta_i = inside ? 1.5 : 1.0, eta_t = inside ? 1.0 : 1.5;
      const double f = fresnel_dielectric(std::abs(wo.z), eta_i, eta_t);
      int reflected = 0;
      constexpr int kN = 100000;
      Rng rng(5, inside);
      for (int i = 0; i < kN; ++i) {
        const auto s = glass->sample(wo, rng.uniform_float(), {0.5f, 0.5f});
        ASSERT_TRUE(s && s->delta);
        if (s->wi.z * wo.z > 0) {
          ++reflected;
          continue;
        }
        // Snell: eta_i sin_i = eta_t sin_t, and the refracted ray is in the plane of incidence.
        const double sin_i = std::sqrt(1 - double(wo.z) * wo.z),
                     sin_t = std::sqrt(1 - double(s->wi.z) * s->wi.z);
        ASSERT_NEAR(eta_i * sin_i, eta_t * sin_t, 1e-5);
        ASSERT_NEAR(s->wi.x * wo.y - s->wi.y * wo.x, 0.0, 1e-6);
        ASSERT_NEAR(s->eta, eta_t / eta_i, 1e-6);
      }
      // Binomial: 4 standard deviations.
      EXPECT_NEAR(double(reflected) / kN, f, 4 * std::sqrt(f * (1 - f) / kN)) << theta << " " << inside;
    }
  }
  // Past the critical angle inside the glass, everything reflects.
  Vec3 wo = direction(60.0f, 0.0f);
  wo.z = -wo.z;
  for (float u : {0.0f, 0.5f, 0.999f}) {
    const auto s = glass->sample(wo, u, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_LT(s->wi.z, 0);
    EXPECT_FLOAT_EQ(s->weight.x, 1.0f);
  }
}

TEST(RenderBsdf, PlasticDiffuseFresnelMatchesKnownValue) {
  // The hemispherical (cosine-weighted) Fresnel reflectance of glass n = 1.5 from outside is ~0.0918.
  const PlasticBsdf plastic({0.5f, 0.5f, 0.5f}, 1.5f, 0.1f);
  EXPECT_NEAR(plastic.diffuse_fresnel(), 0.0918, 5e-4);
}

TEST(RenderBsdf, RejectsOutOfRangeParameters) {
  EXPECT_THROW(make_bsdf(DiffuseMaterial{{1.2f, 0.5f, 0.5f}}), Error);
  EXPECT_THROW(make_bsdf(DielectricMaterial{0.0f}), Error);
  EXPECT_THROW(make_bsdf(PlasticMaterial{{0.5f, 0.5f, 0.5f}, 1.5f, -0.1f}), Error);
  EXPECT_THROW(make_bsdf(ConductorMaterial{{0.2f, 0.2f, -1}, {1, 1, 1}, 0.1f}), Error);
  EXPECT_THROW(make_bsdf(MirrorMaterial{{NAN, 1, 1}}), Error);
}

}  // namespace
}  // namespace lp::render

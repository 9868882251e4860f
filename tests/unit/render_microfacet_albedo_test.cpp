// The directional-albedo tables of the GGX lobe (microfacet_albedo.hpp) against independent Monte Carlo
// estimates: microfacet normals drawn from D(h) cos(theta_h) (Walter et al. 2007), not from the visible
// normals the tables integrate over, with the lobe's D and G.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "engine/bsdf/bsdf_plastic.hpp"
#include "engine/bsdf/microfacet.hpp"
#include "engine/bsdf/microfacet_albedo.hpp"
#include "engine/core/constants.hpp"
#include "engine/core/rng.hpp"
#include "engine/fresnel/dielectric.hpp"

namespace lp::render {
namespace {

struct Estimate {
  double mean = 0, sigma = 0;  // and its standard error
};

// One sample of E_F(mu): h from D(h) cos(theta_h), wi = reflect(wo, h); f |cos wi| / pdf(wi) with
// pdf(wi) = D(h) cos(theta_h) / (4 wo.h), that is F G (wo.h) / (mu cos(theta_h)).
double albedo_sample(const Ggx& ggx, Vec3 wo, const GgxAlbedo::Fresnel& fresnel, Rng& rng) {
  const double u = rng.uniform_double(), phi = 2 * kPi * rng.uniform_double();
  const double alpha = ggx.alpha();
  const double tan2 = alpha * alpha * u / (1 - u);
  const double cos_h = 1 / std::sqrt(1 + tan2), sin_h = std::sqrt(1 - cos_h * cos_h);
  const Vec3 h{float(sin_h * std::cos(phi)), float(sin_h * std::sin(phi)), float(cos_h)};
  const float wo_h = dot(wo, h);
  const Vec3 wi = reflect(wo, h);
  if (wo_h <= 0 || wi.z <= 0) return 0;
  return fresnel(wo_h) * ggx.g(wo, wi) * wo_h / (wo.z * h.z);
}

// E_F(mu, alpha), or with mu < 0 its cosine-weighted mean E_F,avg(alpha) (mu drawn with density 2 mu).
Estimate monte_carlo(float mu, float alpha, const GgxAlbedo::Fresnel& fresnel, int n) {
  const Ggx ggx(alpha);
  Rng rng(2017, uint64_t(alpha * 1e4f + mu * 1e8f));
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const float m = mu >= 0 ? mu : std::sqrt(rng.uniform_float());
    const double x = albedo_sample(ggx, {std::sqrt(1 - m * m), 0, m}, fresnel, rng);
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

const GgxAlbedo::Fresnel kWhite = [](double) { return 1.0; };

// Off the table's nodes; a lookup is within 1e-3 of the integral here (mu > 0.2) and the Monte Carlo
// within 4 standard errors.
const float kPoints[][2] = {{0.25f, 0.1f}, {0.6f, 0.3f}, {0.95f, 0.45f},
                            {0.4f, 0.7f},  {0.8f, 1.0f}, {0.3f, 0.9f}};

TEST(RenderMicrofacetAlbedo, TableMatchesMonteCarlo) {
  for (const auto& [mu, alpha] : kPoints) {
    const float table = ggx_albedo().row(alpha)(mu);
    const Estimate mc = monte_carlo(mu, alpha, kWhite, 1000000);
    std::printf("E(mu %.2f, alpha %.2f): table %.5f, Monte Carlo %.5f +- %.5f\n", double(mu), double(alpha),
                double(table), mc.mean, mc.sigma);
    EXPECT_NEAR(table, mc.mean, 1e-3 + 4 * mc.sigma) << mu << " " << alpha;
  }
}

TEST(RenderMicrofacetAlbedo, AverageMatchesMonteCarlo) {
  for (float alpha : {0.05f, 0.25f, 0.6f, 1.0f}) {
    const float table = ggx_albedo().row(alpha).average();
    const Estimate mc = monte_carlo(-1, alpha, kWhite, 1000000);
    std::printf("E_avg(alpha %.2f): table %.5f, Monte Carlo %.5f +- %.5f\n", double(alpha), double(table),
                mc.mean, mc.sigma);
    EXPECT_NEAR(table, mc.mean, 1e-3 + 4 * mc.sigma) << alpha;
  }
}

TEST(RenderMicrofacetAlbedo, CoatTableMatchesMonteCarlo) {
  // The dielectric coat of the glTF model (index 1.5) and a single-alpha table of another index.
  const DielectricCoat coat(1.5f);
  for (const auto& [mu, alpha] : kPoints) {
    const GgxAlbedo::Fresnel f = [](double c) { return fresnel_dielectric(c, 1.0, 1.5); };
    const Estimate mc = monte_carlo(mu, alpha, f, 1000000);
    EXPECT_NEAR(coat.single_scattering.row(alpha)(mu), mc.mean, 1e-3 + 4 * mc.sigma) << mu << " " << alpha;
  }
  const DielectricCoat one(2.5f, 0.35f);
  const GgxAlbedo::Fresnel f = [](double c) { return fresnel_dielectric(c, 1.0, 2.5); };
  for (float mu : {0.3f, 0.7f}) {
    const Estimate mc = monte_carlo(mu, 0.35f, f, 1000000);
    EXPECT_NEAR(one.single_scattering.row(0.35f)(mu), mc.mean, 1e-3 + 4 * mc.sigma) << mu;
  }
  // Fdr of index 1.5 (a known value) and a mirror's row: F itself.
  EXPECT_NEAR(coat.fresnel_average, 0.0918, 5e-4);
  for (int node : {0, 10, GgxAlbedo::kNodes - 1}) {
    const float x = float(node) / (GgxAlbedo::kNodes - 1), mu = x * x;
    EXPECT_NEAR(coat.single_scattering.row(0)(mu), fresnel_dielectric(mu, 1.0, 1.5), 1e-6);
  }
}

TEST(RenderMicrofacetAlbedo, CosineWeightedMeanIsExactForPolynomials) {
  // 2 integral of mu^k mu dmu = 2 / (k + 2).
  EXPECT_NEAR(cosine_weighted_mean([](double) { return 1.0; }), 1.0, 1e-12);
  EXPECT_NEAR(cosine_weighted_mean([](double mu) { return mu * mu; }), 0.5, 1e-7);
  // Schlick's F: f0 + (1 - f0) / 21.
  EXPECT_NEAR(cosine_weighted_mean([](double mu) { return 0.04 + 0.96 * std::pow(1 - mu, 5); }),
              0.04 + 0.96 / 21, 1e-7);
}

}  // namespace
}  // namespace lp::render

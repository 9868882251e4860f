#pragma once
// The directional albedo of the Ggx reflection lobe (microfacet.hpp) with a Fresnel factor F,
//   E_F(mu, alpha) = integral over wi of F(wo.h) D(h) G(wo, wi) / (4 mu) dwi,   mu = wo.z,
// the fraction of the light arriving from wo that one scattering off the microfacets returns, and its
// cosine-weighted mean E_F,avg(alpha) = 2 integral of E_F(mu) mu dmu. Multiple-scattering compensation
// (microfacet_multiscatter.hpp) is built on them.
//
// A table holds E_F on 32 x 32 nodes, mu = x^2 and alpha = y^2 for x, y uniform in [0, 1] (the nodes
// crowd towards grazing mu and small alpha, where E_F changes fastest); lookups are bilinear in (x, y).
// Each node is a quadrature of our own lobe through its visible-normal sampling (Ggx::
// sample_visible_normal; see microfacet_albedo.cpp), so the table is of the lobe the BSDFs evaluate,
// not of a model of it. At alpha = 0 the lobe is a mirror: E_F = F(mu).
// Accuracy of a lookup against the exact integral, F = 1 (measured against 4 million-point quadratures):
// the nodes within 2e-4; between nodes within 1e-3 for mu > 0.2, 3e-3 for mu > 0.05; worse only where
// both mu and alpha are near 0 (E_F dips at mu ~ alpha there, up to 7% missed at alpha < 0.01 and
// mu < 0.01: silhouette pixels of near-mirrors). The averages are those of the interpolated tables, so
// a lobe normalised by them integrates exactly to what it should.
//
// The tables are computed at first use (tens of milliseconds each, once per process) rather than
// generated and committed: they then cannot drift from the Ggx code they integrate, and a coat of any
// index gets its own table the same way.
#include <functional>
#include <vector>

namespace lp::render {

// 2 * integral over [0, 1] of f(mu) mu dmu: the mean of f(cos theta) over the hemisphere, weighted by
// cos theta (midpoint rule, 4096 steps, in double; for smooth f the error is ~1e-7).
double cosine_weighted_mean(const std::function<double(double)>& f);

class GgxAlbedo;

// E_F(mu, alpha) at one point by the quadrature the tables are built with
// (visible_normal_quadrature.hpp): within 2.2e-4 of the exact integral for mu in [0.02, 1] and alpha in
// [0.01, 1].
double ggx_albedo_quadrature(const std::function<double(double cos_theta)>& fresnel, float mu, float alpha);

class GgxAlbedo {
 public:
  using Fresnel = std::function<double(double cos_theta)>;  // F(wo.h), in [0, 1]
  static constexpr int kNodes = 32;                         // per axis

  // Every alpha in [0, 1].
  explicit GgxAlbedo(const Fresnel& fresnel);
  // One alpha only: row() then ignores its argument.
  GgxAlbedo(const Fresnel& fresnel, float alpha);

  // E_F(mu) and E_F,avg at one alpha: the two rows of nodes around it, blended. It points into the
  // table, which must outlive it.
  class Row {
   public:
    float operator()(float mu) const;
    float average() const { return average_; }

   private:
    friend class GgxAlbedo;
    Row(const float* lo, const float* hi, float w, float average)
        : lo_(lo), hi_(hi), w_(w), average_(average) {}
    const float *lo_, *hi_;
    float w_, average_;
  };
  Row row(float alpha) const;

 private:
  void add_row(const Fresnel& fresnel, float alpha);

  std::vector<float> e_;         // [alpha node][mu node]
  std::vector<float> averages_;  // per alpha node
};

// F = 1: the albedo of the bare lobe (computed at first use; thread-safe).
const GgxAlbedo& ggx_albedo();

}  // namespace lp::render

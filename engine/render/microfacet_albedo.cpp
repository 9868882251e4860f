#include "engine/render/microfacet_albedo.hpp"

#include <algorithm>
#include <cmath>

#include "engine/render/microfacet.hpp"

namespace lp::render {
namespace {

constexpr int kLast = GgxAlbedo::kNodes - 1;

// Node i of either axis: x^2 for x = i / kLast.
float node_value(int i) {
  const float x = float(i) / kLast;
  return x * x;
}

}  // namespace

// E_F(mu, alpha) as the mean over visible normals h of F(wo.h) G(wo, wi) / G1(wo), wi = reflect(wo, h),
// zero where wi is below the surface. The sampler maps u1 to the squared radius on a disk; the normals
// that send wi below the horizon lie at its rim, a band of width ~alpha^2 in u1, so u1 = 1 - (1 - t)^3
// with t on 64 midpoints crowds points there. The integrand is symmetric about the plane of incidence
// (u2 -> 0.5 - u2), so u2 covers half the disk, [0.25, 0.75], on 8 midpoints. Measured error below
// 2.2e-4 for mu in [0.02, 1] and alpha in [0.01, 1] (against 8192 x 512 points).
double ggx_albedo_quadrature(const GgxAlbedo::Fresnel& fresnel, float mu, float alpha) {
  constexpr int kRadial = 64, kAngular = 8;
  const Ggx ggx(alpha);
  mu = std::max(mu, 1e-4f);  // grazing: the limit
  const Vec3 wo{std::sqrt(1.0f - mu * mu), 0.0f, mu};
  double sum = 0;
  for (int i = 0; i < kRadial; ++i) {
    const double s = 1.0 - (i + 0.5) / kRadial;  // 1 - t
    const float u1 = float(1.0 - s * s * s);
    double ring = 0;
    for (int j = 0; j < kAngular; ++j) {
      const float u2 = 0.25f + 0.5f * (float(j) + 0.5f) / kAngular;
      const Vec3 h = ggx.sample_visible_normal(wo, u1, u2);
      const Vec3 wi = reflect(wo, h);
      if (wi.z > 0) ring += fresnel(dot(wo, h)) * ggx.g(wo, wi) / ggx.g1(wo);
    }
    sum += ring * 3.0 * s * s;  // du1 / dt
  }
  return sum / (kRadial * kAngular);
}

double cosine_weighted_mean(const std::function<double(double)>& f) {
  constexpr int kSteps = 4096;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    sum += f(mu) * mu;
  }
  return 2.0 * sum / kSteps;
}

GgxAlbedo::GgxAlbedo(const Fresnel& fresnel) {
  e_.reserve(kNodes * kNodes);
  for (int j = 0; j < kNodes; ++j) add_row(fresnel, node_value(j));
}

GgxAlbedo::GgxAlbedo(const Fresnel& fresnel, float alpha) {
  add_row(fresnel, alpha);
}

void GgxAlbedo::add_row(const Fresnel& fresnel, float alpha) {
  const size_t start = e_.size();
  for (int i = 0; i < kNodes; ++i) {
    const float mu = node_value(i);
    e_.push_back(float(alpha > 0 ? ggx_albedo_quadrature(fresnel, mu, alpha) : fresnel(mu)));
  }
  const Row row(&e_[start], &e_[start], 0.0f, 0.0f);
  averages_.push_back(float(cosine_weighted_mean([&](double mu) { return row(float(mu)); })));
}

float GgxAlbedo::Row::operator()(float mu) const {
  const float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * kLast;
  const int i = std::min(int(x), kLast - 1);
  const float f = x - float(i);
  const float lo = lo_[i] + f * (lo_[i + 1] - lo_[i]);
  const float hi = hi_[i] + f * (hi_[i + 1] - hi_[i]);
  return lo + w_ * (hi - lo);
}

GgxAlbedo::Row GgxAlbedo::row(float alpha) const {
  const float* e = e_.data();
  if (averages_.size() == 1) return {e, e, 0.0f, averages_[0]};
  const float y = std::sqrt(std::clamp(alpha, 0.0f, 1.0f)) * kLast;
  const int j = std::min(int(y), kLast - 1);
  const float w = y - float(j);
  return {e + j * kNodes, e + (j + 1) * kNodes, w, averages_[j] + w * (averages_[j + 1] - averages_[j])};
}

const GgxAlbedo& ggx_albedo() {
  static const GgxAlbedo table([](double) { return 1.0; });
  return table;
}

}  // namespace lp::render

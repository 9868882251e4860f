#include "engine/bsdf/microfacet_albedo.hpp"

#include <algorithm>
#include <cmath>

#include "engine/bsdf/visible_normal_quadrature.hpp"

namespace lp::render {
namespace {

constexpr int kLast = GgxAlbedo::kNodes - 1;

// Node i of either axis: x^2 for x = i / kLast.
float node_value(int i) {
  const float x = float(i) / kLast;
  return x * x;
}

}  // namespace

double ggx_albedo_quadrature(const GgxAlbedo::Fresnel& fresnel, float mu, float alpha) {
  double sum = 0;
  visible_normal_quadrature(mu, alpha,
                            [&](float cos_theta, double weight) { sum += fresnel(cos_theta) * weight; });
  return sum;
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

#include "engine/bsdf/sheen_lobe.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine/core/constants.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

float sheen_alpha(float roughness) {
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  return std::max(r * r, kMinSheenAlpha);
}

// D(h) V for a white colour; cos_h = h.z.
double charlie(double cos_h, double cos_o, double cos_i, double alpha) {
  const double sin2_h = std::max(0.0, 1.0 - cos_h * cos_h);
  const double d = (2.0 + 1.0 / alpha) * std::pow(sin2_h, 0.5 / alpha) / (2.0 * kPi);
  const double v = 1.0 / (4.0 * (cos_i + cos_o - cos_i * cos_o));
  return d * v;
}

// E(mu, alpha) on kNodes x kNodes nodes, mu and alpha uniform in [0, 1] (alpha's first node at
// kMinSheenAlpha); bilinear between them.
class SheenAlbedoTable {
 public:
  static constexpr int kNodes = 32;

  SheenAlbedoTable() : e_(size_t(kNodes * kNodes)) {
    for (int a = 0; a < kNodes; ++a)
      for (int m = 0; m < kNodes; ++m)
        e_[size_t(a * kNodes + m)] = float(integrate(node_mu(m), node_alpha(a)));
  }

  float operator()(float mu, float alpha) const {
    const float x = std::clamp(mu, 0.0f, 1.0f) * (kNodes - 1);
    const float y = std::clamp((alpha - kMinSheenAlpha) / (1.0f - kMinSheenAlpha), 0.0f, 1.0f) * (kNodes - 1);
    const int i = std::min(int(x), kNodes - 2), j = std::min(int(y), kNodes - 2);
    const float fx = x - float(i), fy = y - float(j);
    const auto at = [this](int jj, int ii) { return e_[size_t(jj * kNodes + ii)]; };
    const float lo = at(j, i) * (1 - fx) + at(j, i + 1) * fx;
    const float hi = at(j + 1, i) * (1 - fx) + at(j + 1, i + 1) * fx;
    return lo * (1 - fy) + hi * fy;
  }

 private:
  static double node_mu(int m) { return std::max(1e-3, double(m) / (kNodes - 1)); }
  static double node_alpha(int a) {
    return kMinSheenAlpha + (1.0 - kMinSheenAlpha) * double(a) / (kNodes - 1);
  }

  // integral of D V cos_i over the hemisphere, midpoint rule in (cos_i, phi); phi symmetric about 0.
  static double integrate(double mu, double alpha) {
    constexpr int kCos = 256, kPhi = 128;
    const double so = std::sqrt(std::max(0.0, 1 - mu * mu));
    double sum = 0;
    for (int i = 0; i < kCos; ++i) {
      const double ci = (i + 0.5) / kCos, si = std::sqrt(1 - ci * ci);
      for (int j = 0; j < kPhi; ++j) {
        const double phi = (j + 0.5) / kPhi * kPi;
        const double hx = so + si * std::cos(phi), hy = si * std::sin(phi), hz = mu + ci;
        const double cos_h = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
        sum += charlie(cos_h, mu, ci, alpha) * ci;
      }
    }
    return sum * (1.0 / kCos) * (kPi / kPhi) * 2.0;
  }

  std::vector<float> e_;
};

const SheenAlbedoTable& sheen_albedo_table() {
  static const SheenAlbedoTable table;
  return table;
}

}  // namespace

SheenLobe::SheenLobe(Rgb color, float roughness) : color_(color), alpha_(sheen_alpha(roughness)) {}

Rgb SheenLobe::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  const Vec3 h = normalize(wo + wi);
  const float excess = std::max({1.0f, raw_albedo(wo.z), raw_albedo(wi.z)});
  return color_ * float(charlie(h.z, wo.z, wi.z, alpha_) * wi.z / excess);
}

float SheenLobe::raw_albedo(float cos_o) const {
  return sheen_albedo_table()(cos_o, alpha_);
}

float SheenLobe::albedo(float cos_o) const {
  return std::min(1.0f, raw_albedo(cos_o));
}

float SheenLobe::pdf(Vec3 wi) {
  return wi.z > 0 ? cosine_hemisphere_pdf(wi.z) : 0.0f;
}

Vec3 SheenLobe::sample(Point2 u) {
  return square_to_cosine_hemisphere(u.x, u.y);
}

}  // namespace lp::render

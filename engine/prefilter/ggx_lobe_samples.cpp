#include "engine/prefilter/ggx_lobe_samples.hpp"

#include <cmath>

#include "engine/bsdf/microfacet.hpp"
#include "engine/core/constants.hpp"
#include "engine/envmap/sample_set.hpp"

namespace lp {
namespace {

// The scramble of the Sobol points: fixed, so a chain is the same on every run.
constexpr uint64_t kSobolSeed = 0x9f1e3a5c2b7d4e61ULL;
constexpr Vec3 kAxis{0, 0, 1};

float alpha_of(double roughness) {
  return float(roughness * roughness);
}

}  // namespace

std::vector<LobeSample> ggx_lobe_samples(double roughness, int count) {
  // Visible normals seen from the axis itself are distributed as D(h) (n.h): G1 of the axis is 1.
  const render::Ggx ggx(alpha_of(roughness));
  std::vector<LobeSample> samples;
  samples.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    const Point2 u = sobol_point(kSobolSeed, uint64_t(i));
    const Vec3 h = ggx.sample_visible_normal(kAxis, u.x, u.y);
    const Vec3 l = render::reflect(kAxis, h);
    if (l.z <= 0) continue;
    const float pdf = ggx.reflection_pdf(kAxis, h);
    if (!(pdf > 0)) continue;
    samples.push_back({l, l.z, 1.0f / (float(count) * pdf)});
  }
  return samples;
}

double smallest_sample_solid_angle(double roughness, int count) {
  const double alpha = std::max(double(alpha_of(roughness)), 1e-4);  // as Ggx clamps it
  return 4.0 * kPi * alpha * alpha / count;
}

}  // namespace lp

#include "engine/prefilter/lobe_convolution.hpp"

#include <cmath>

#include "engine/prefilter/ggx_lobe_samples.hpp"

namespace lp {
namespace {

// A frame around n whose first axes follow theta and phi: it turns smoothly with n everywhere but at
// the poles, so the fixed pattern of the samples leaves no seam in a level.
struct Frame {
  Vec3 s, t, n;
};

Frame frame_around(Vec3 n) {
  const float r = std::hypot(n.x, n.y);
  const Vec3 t = r > 1e-6f ? Vec3{-n.y / r, n.x / r, 0} : Vec3{0, 1, 0};
  return {cross(t, n), t, n};
}

}  // namespace

LobeConvolution::LobeConvolution(const PrefilterSource& source, double roughness, int samples)
    : source_(source) {
  const auto lobe = ggx_lobe_samples(roughness, samples);
  double total = 0;
  for (const LobeSample& s : lobe) total += s.weight;
  taps_.reserve(lobe.size());
  for (const LobeSample& s : lobe)
    taps_.push_back({s.direction, float(s.weight / total), source.lod(s.solid_angle)});
  // Every sample below the horizon (a few samples of a rough lobe): the lobe's axis, read as wide as it.
  if (taps_.empty())
    taps_.push_back({{0, 0, 1}, 1.0f, source.lod(float(smallest_sample_solid_angle(roughness, 1)))});
}

Rgb LobeConvolution::radiance(Vec3 n) const {
  const Frame f = frame_around(n);
  Rgb sum;
  for (const Tap& tap : taps_) {
    const Vec3 l = f.s * tap.direction.x + f.t * tap.direction.y + f.n * tap.direction.z;
    sum += source_.radiance(l, tap.lod) * tap.weight;
  }
  return sum;
}

}  // namespace lp

#include "engine/render/aux_passes.hpp"

#include <limits>

#include "engine/render/integrator.hpp"

namespace lp::render {

void aux_values(const PathSample& s, const PassSet& passes, float* out) {
  const auto put3 = [&](AuxPass p, Vec3 v) {
    float* o = out + passes.offset(p);
    o[0] = v.x, o[1] = v.y, o[2] = v.z;
  };
  if (passes.has(AuxPass::Albedo)) put3(AuxPass::Albedo, s.albedo);
  if (passes.has(AuxPass::Normal)) put3(AuxPass::Normal, s.normal);
  if (passes.has(AuxPass::Depth)) {
    float* o = out + passes.offset(AuxPass::Depth);
    o[0] = s.hit ? s.depth : 0.0f;
    o[1] = s.hit ? 1.0f : 0.0f;
  }
  if (passes.has(AuxPass::Alpha)) out[passes.offset(AuxPass::Alpha)] = s.alpha;
}

Rgb aux_mean(AuxPass p, const PassSet& passes, const double* sums, double count) {
  const double* c = sums + passes.offset(p);
  if (p == AuxPass::Depth) {
    const float d = c[1] > 0 ? float(c[0] / c[1]) : std::numeric_limits<float>::infinity();
    return {d, d, d};
  }
  if (!(count > 0)) return {};
  if (p == AuxPass::Alpha) {
    const float a = float(c[0] / count);
    return {a, a, a};
  }
  return {float(c[0] / count), float(c[1] / count), float(c[2] / count)};
}

void aux_sums(AuxPass p, const PassSet& passes, Rgb mean, double count, double* sums) {
  double* c = sums + passes.offset(p);
  if (p == AuxPass::Depth) {
    const bool hit = std::isfinite(mean.x);
    c[0] = hit ? double(mean.x) * count : 0;
    c[1] = hit ? count : 0;
  } else if (p == AuxPass::Alpha) {
    c[0] = double(mean.x) * count;
  } else {
    c[0] = double(mean.x) * count, c[1] = double(mean.y) * count, c[2] = double(mean.z) * count;
  }
}

Image aux_image(AuxPass p, const PassSet& passes, int width, int height, std::span<const double> sums,
                std::span<const uint32_t> counts) {
  Image image(width, height);
  const size_t channels = size_t(passes.channels());
  auto out = image.data();
  for (size_t i = 0; i < counts.size(); ++i) {
    const Rgb v = aux_mean(p, passes, &sums[i * channels], counts[i]);
    out[i * 3] = v.x, out[i * 3 + 1] = v.y, out[i * 3 + 2] = v.z;
  }
  return image;
}

}  // namespace lp::render

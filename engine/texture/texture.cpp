#include "engine/texture/texture.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"

namespace lp {
namespace {

Rgba lerp(const Rgba& a, const Rgba& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t};
}

}  // namespace

Texture::Texture(int width, int height, int channels, std::vector<float> texels) : channels_(channels) {
  if (width <= 0 || height <= 0 || (channels != 3 && channels != 4) ||
      texels.size() != size_t(width) * size_t(height) * size_t(channels))
    throw Error(ErrorKind::Internal, "texture texels do not match its size");
  levels_ = build_mip_pyramid(MipLevel{width, height, std::move(texels)}, channels);
}

float Texture::level_for_footprint(float uv_width) const {
  const float texels = uv_width * std::sqrt(float(width()) * float(height()));
  if (!(texels > 1.0f)) return 0.0f;  // also NaN
  return std::min(std::log2(texels), float(level_count() - 1));
}

Rgba Texture::texel(int level, int x, int y) const {
  const MipLevel& l = levels_[size_t(level)];
  const float* t = &l.texels[(size_t(y) * size_t(l.width) + size_t(x)) * size_t(channels_)];
  return {t[0], t[1], t[2], channels_ == 4 ? t[3] : 1.0f};
}

Rgba Texture::bilinear(int level, Point2 uv, const TextureSampler& sampler) const {
  const MipLevel& l = levels_[size_t(level)];
  const float x = reduce_coordinate(uv.x, sampler.wrap_s) * float(l.width) - 0.5f;
  const float y = reduce_coordinate(uv.y, sampler.wrap_t) * float(l.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const int x0 = int(fx), y0 = int(fy);
  const float tx = x - fx, ty = y - fy;
  const int xa = wrap_texel(x0, l.width, sampler.wrap_s), xb = wrap_texel(x0 + 1, l.width, sampler.wrap_s);
  const int ya = wrap_texel(y0, l.height, sampler.wrap_t), yb = wrap_texel(y0 + 1, l.height, sampler.wrap_t);
  const Rgba top = lerp(texel(level, xa, ya), texel(level, xb, ya), tx);
  const Rgba bottom = lerp(texel(level, xa, yb), texel(level, xb, yb), tx);
  return lerp(top, bottom, ty);
}

Rgba Texture::sample(Point2 uv, float level, const TextureSampler& sampler) const {
  const float top = float(level_count() - 1);
  const float l = std::isnan(level) ? 0.0f : std::clamp(level, 0.0f, top);
  const int l0 = int(l);
  const float t = l - float(l0);
  const Rgba a = bilinear(l0, uv, sampler);
  if (t == 0.0f) return a;
  return lerp(a, bilinear(l0 + 1, uv, sampler), t);
}

// Probes of the minor width whose centres span the major width less one minor width cover the ellipse
// end to end without gaps; their number grows continuously from one for a round footprint.
Rgba Texture::sample(Point2 uv, const UvFootprint& footprint, float max_anisotropy,
                     const TextureSampler& sampler) const {
  const FootprintAxes axes = principal_axes(footprint);
  const float minor = std::max(axes.minor_width, axes.major_width / max_anisotropy);
  const float level = level_for_footprint(minor);
  const float ratio = axes.major_width / minor;
  const int probes = ratio > 1 ? int(std::ceil(std::min(ratio, max_anisotropy))) : 1;  // also NaN
  if (probes == 1) return sample(uv, level, sampler);
  const float span = axes.major_width - minor, step = span / float(probes - 1);
  Rgba sum{0, 0, 0, 0};
  for (int i = 0; i < probes; ++i) {
    const float s = step * float(i) - 0.5f * span;
    const Rgba t = sample({uv.x + axes.major.x * s, uv.y + axes.major.y * s}, level, sampler);
    sum = {sum.r + t.r, sum.g + t.g, sum.b + t.b, sum.a + t.a};
  }
  const float w = 1.0f / float(probes);
  return {sum.r * w, sum.g * w, sum.b * w, sum.a * w};
}

int64_t Texture::memory_bytes() const {
  int64_t bytes = 0;
  for (const MipLevel& l : levels_) bytes += int64_t(l.texels.size() * sizeof(float));
  return bytes;
}

}  // namespace lp

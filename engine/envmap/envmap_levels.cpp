#include "engine/envmap/envmap_levels.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "engine/texture/mip_pyramid.hpp"

namespace lp {
namespace {

// The filter runs on (L w, w), w a row's solid angle per unit of v, so (L w) / w of a coarse texel is the
// solid-angle mean of the radiance it covers and a constant map stays constant. Odd sizes blend rows by
// area rather than solid angle, which moves the level's power by about 1e-5; one scale per channel puts
// it back, since light sampling depends on the power being the map's.
constexpr int kChannels = 4;

// Row y of the image as (L w, w) texels.
const float* weighted_row(const Image& image, int y, float* out) {
  const float w = float(latlong::pixel_solid_angle(y, 1, image.height()) * image.height() / (2.0 * kPi));
  for (int x = 0; x < image.width(); ++x) {
    const Rgb c = image.at(x, y);
    float* t = &out[size_t(x) * kChannels];
    t[0] = c.x * w, t[1] = c.y * w, t[2] = c.z * w, t[3] = w;
  }
  return out;
}

Image unweighted(const MipLevel& level, const Rgb& power) {
  Image out(level.width, level.height);
  tbb::parallel_for(0, level.height, [&](int y) {
    for (int x = 0; x < level.width; ++x) {
      const float* t = &level.texels[(size_t(y) * level.width + x) * kChannels];
      out.set(x, y, Rgb{t[0], t[1], t[2]} / t[3]);
    }
  });
  const Rgb level_power = EnvMap::power_of(out);
  const auto ratio = [](float want, float have) { return have > 0 ? want / have : 1.0f; };
  const Rgb scale{ratio(power.x, level_power.x), ratio(power.y, level_power.y),
                  ratio(power.z, level_power.z)};
  for (int y = 0; y < level.height; ++y)
    for (int x = 0; x < level.width; ++x) out.set(x, y, out.at(x, y) * scale);
  return out;
}

}  // namespace

// Level 1 is filtered from the image weighted a row at a time: a weighted copy of the whole map would
// take 16 bytes a pixel while the levels are made.
EnvMapLevels::EnvMapLevels(const EnvMap& map, int coarsest) : base_(map.image()) {
  const Image& image = map.image();
  images_.push_back(&base_);
  if (coarsest < 1 || (image.width() == 1 && image.height() == 1)) return;
  MipLevel current = downsample(image.width(), image.height(), kChannels,
                                [&](int y, float* scratch) { return weighted_row(image, y, scratch); });
  levels_.push_back(unweighted(current, map.power()));
  for (int k = 2; k <= coarsest && (current.width > 1 || current.height > 1); ++k) {
    current = downsample(current, kChannels);
    levels_.push_back(unweighted(current, map.power()));
  }
  top_ = std::make_shared<const EnvMap>(std::move(levels_.back()));
  levels_.pop_back();
  for (const Image& level : levels_) images_.push_back(&level);
  images_.push_back(&top_->image());
}

int64_t EnvMapLevels::memory_bytes(int width, int height, int coarsest) {
  int64_t bytes = 0;
  for (int k = 1; k <= coarsest && (width > 1 || height > 1); ++k) {
    width = std::max(1, width / 2), height = std::max(1, height / 2);
    bytes += EnvMap::image_bytes(width, height);
  }
  return bytes;
}

int EnvMapLevels::level_for_width(int width, int max_width) {
  int k = 0;
  for (; width > std::max(1, max_width); width = std::max(1, width / 2)) ++k;
  return k;
}

Rgb EnvMapLevels::bilinear(int k, latlong::Uv uv) const {
  const Image& image = level(k);
  const int w = image.width(), h = image.height();
  const float fx = uv.u * float(w) - 0.5f, fy = uv.v * float(h) - 0.5f;
  const float x0f = std::floor(fx), y0f = std::floor(fy);
  const float tx = fx - x0f, ty = fy - y0f;
  // fx is in [-0.5, w - 0.5] for u in [0, 1]: x0 in [-1, w - 1], wrapped without integer division.
  const int x = int(x0f);
  const int x0 = x < 0 ? x + w : x, x1 = x + 1 >= w ? x + 1 - w : x + 1;
  const int y0 = std::clamp(int(y0f), 0, h - 1), y1 = std::clamp(int(y0f) + 1, 0, h - 1);
  const Rgb top = image.at(x0, y0) * (1 - tx) + image.at(x1, y0) * tx;
  const Rgb bottom = image.at(x0, y1) * (1 - tx) + image.at(x1, y1) * tx;
  return top * (1 - ty) + bottom * ty;
}

Rgb EnvMapLevels::trilinear(latlong::Uv uv, float level) const {
  const float l = std::clamp(level, 0.0f, float(coarsest()));
  const int k = std::min(int(l), coarsest());
  const float t = l - float(k);
  if (t <= 0 || k == coarsest()) return bilinear(k, uv);
  return bilinear(k, uv) * (1 - t) + bilinear(k + 1, uv) * t;
}

float EnvMapLevels::level_for_angle(float angle) const {
  const float texel = kPiF / float(base_.height());
  return angle > 0 ? std::log2(angle / texel) : 0.0f;
}

}  // namespace lp

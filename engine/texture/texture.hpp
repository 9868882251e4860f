#pragma once
// An image texture: linear float RGB or RGBA texels and their mip pyramid, built once at construction.
// Texture coordinates follow glTF: (0, 0) is the top-left corner of the image, u along the columns,
// v down the rows; texel (x, y) of a level of w x h texels has its centre at ((x + 0.5) / w, (y + 0.5) / h).
#include <cstdint>
#include <vector>

#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"
#include "engine/texture/mip_pyramid.hpp"
#include "engine/texture/texture_footprint.hpp"
#include "engine/texture/wrap_mode.hpp"

namespace lp {

struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
  Rgb rgb() const { return {r, g, b}; }
};

class Texture {
 public:
  // `texels` holds width * height * channels floats (channels 3 or 4), row 0 at the top.
  Texture(int width, int height, int channels, std::vector<float> texels);

  int channels() const { return channels_; }
  int level_count() const { return int(levels_.size()); }
  int width(int level = 0) const { return levels_[size_t(level)].width; }
  int height(int level = 0) const { return levels_[size_t(level)].height; }
  // The size of one texel of `level` in texture coordinates (1 / width, 1 / height).
  Point2 texel_size(int level = 0) const { return {1.0f / float(width(level)), 1.0f / float(height(level))}; }
  // The level whose texels are as wide as a footprint of `uv_width` in texture coordinates: log2 of the
  // footprint in level-0 texels (the geometric mean of width and height), clamped to the pyramid.
  float level_for_footprint(float uv_width) const;

  // Trilinear: bilinear in the two levels around `level` (fractional, clamped to the pyramid), blended.
  Rgba sample(Point2 uv, float level, const TextureSampler& sampler = {}) const;
  // Over an elliptical footprint: trilinear probes spread along its major axis, each at the level of
  // the minor width, their mean. The ellipse is first made no more than `max_anisotropy` times longer
  // than wide (by widening it); a round footprint takes one probe, the same as sample(uv, level).
  Rgba sample(Point2 uv, const UvFootprint& footprint, float max_anisotropy,
              const TextureSampler& sampler = {}) const;
  // Bilinear in level 0 only (no mip mapping).
  Rgba sample_bilinear(Point2 uv, const TextureSampler& sampler = {}) const {
    return bilinear(0, uv, sampler);
  }
  // The stored texel of a level (wrapped), without filtering.
  Rgba texel(int level, int x, int y) const;

  const MipLevel& level(int i) const { return levels_[size_t(i)]; }
  int64_t memory_bytes() const;

 private:
  Rgba bilinear(int level, Point2 uv, const TextureSampler& sampler) const;

  int channels_;
  std::vector<MipLevel> levels_;
};

}  // namespace lp

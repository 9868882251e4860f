#pragma once
// Importance sampling of an environment map: pixel weights luminance * sin(theta of the row centre),
// solid-angle pdf = p(u, v) / (2 pi^2 sin theta) with theta of the sample itself.
// With SamplerWeights::MisCompensated (envmap.hpp), the weights are max(0, luminance - mean luminance)
// * sin(theta); a map no pixel of which is above its mean (a uniform one) keeps the plain weights.
// Samples carry the pixel's whole radiance either way.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>

#include "engine/core/constants.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/sampling/alias_table_2d.hpp"
#include "engine/sampling/piecewise_constant_2d.hpp"

namespace lp {

struct EnvSample {
  int pixel_x = 0, pixel_y = 0;
  float u = 0, v = 0;
  Vec3 direction;
  float theta = 0, phi = 0;
  float pdf = 0;  // solid-angle density
  Rgb radiance;   // the radiance of the sampled pixel (the same grid as the pdf)
};

class EnvMapSampler {
 public:
  EnvMapSampler(const EnvMap& map, LuminanceMode mode, SamplerWeights weights = SamplerWeights::Radiance);
  // The bytes a sampler of a width x height map holds: its inverse CDFs. The alias table is a cache
  // entry of the map of its own (alias_table), made and reserved only where independent samples are drawn.
  static int64_t memory_bytes(int64_t width, int64_t height) {
    return PiecewiseConstant2D::memory_bytes(width, height);
  }

  // Inverse-CDF sample: u1 -> phi (column), u2 -> theta (row). Both in [0, 1).
  EnvSample sample(float u1, float u2) const;
  // The alias table of the distribution, built on first use and cached on the map with its bytes
  // (evicted like other derived data; a holder keeps it alive).
  std::shared_ptr<const AliasTable2D> alias_table() const;
  // O(1) alias-table sample from independent random bits (for independent sample sets); `table` is
  // alias_table().
  EnvSample sample_alias(const AliasTable2D& table, uint64_t r_row, uint64_t r_col, float fu, float fv) const;
  // The same for many samples at once: the table entries, pdfs and pixels each one needs are
  // prefetched a block ahead, so their cache misses overlap instead of following one another.
  struct AliasBits {
    uint64_t r_row, r_col;
    float fu, fv;
  };
  void sample_alias(const AliasTable2D& table, std::span<const AliasBits> bits,
                    std::span<EnvSample> out) const;

  // Solid-angle pdf of a direction; agrees with sample().pdf.
  float pdf(Vec3 direction) const;
  // The same for a direction already located in pixel (x, y), with its sin(theta).
  float pdf(int x, int y, float sin_theta) const { return solid_angle_pdf(dist_.density(x, y), sin_theta); }
  // Starts loading the pdf and radiance of pixel (x, y), for a caller that knows it ahead of its use.
  void prefetch(int x, int y) const {
    dist_.prefetch(x, y);
    __builtin_prefetch(map_.image().row(y) + 3 * x);
  }

  // The distribution over pixels; its rows' weights are their mean luminance (less the offset, per
  // pixel, when compensated) * sin(theta).
  const PiecewiseConstant2D& distribution() const { return dist_; }
  double row_mean_luminance(int y) const;
  const EnvMap& map() const { return map_; }
  LuminanceMode mode() const { return mode_; }
  // The luminance taken off every pixel's weight: the map's mean when compensated, else 0.
  float luminance_offset() const { return offset_; }

 private:
  // p / (2 pi^2 sin theta), with sin theta clamped away from zero so that samples at the exact pole
  // give a large finite pdf rather than Inf.
  static float solid_angle_pdf(float density, float sin_theta) {
    return density / (2.0f * kPiF * kPiF * std::max(sin_theta, 1e-7f));
  }
  EnvSample finish(const GridSample& g) const;

  const EnvMap& map_;
  LuminanceMode mode_;
  float offset_;
  PiecewiseConstant2D dist_;
};

}  // namespace lp

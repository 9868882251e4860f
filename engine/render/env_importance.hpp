#pragma once
// A faster sampler for the environment map's importance distribution, for the renderer's inner loop:
// the same density as EnvMapSampler (pixel weights luminance * sin(theta of the row centre), the
// solid-angle pdf p(u, v) / (2 pi^2 sin theta)), so its pdf is EnvMapSampler::pdf, but the inverse
// CDFs are searched through guide tables (Chen & Asau 1974): one table lookup and a search over a
// few entries instead of a binary search over the whole row, and each pixel's CDF entry sits beside
// its pdf, so a sample touches few cache lines. Monotone in (u1, u2): low-discrepancy points stay so.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp::render {

struct ImportanceSample {
  Vec3 direction;  // map space
  float pdf = 0;   // solid angle
  Rgb radiance;    // of the sampled pixel
};

// The map pixel a direction falls in, located ahead of its use (its data is prefetched).
struct EnvPixel {
  int x = 0, y = 0;
  float sin_theta = 1;
};

class EnvImportance {
 public:
  explicit EnvImportance(const EnvMapSampler& sampler);
  // The bytes the tables of a width x height map hold.
  static int64_t memory_bytes(int64_t width, int64_t height);

  // Built once per map and cached on it.
  static std::shared_ptr<const EnvImportance> of(const EnvMap& map);

  // u1 picks the column within the row, u2 the row, as EnvMapSampler::sample.
  ImportanceSample sample(float u1, float u2) const;

  // The pixel of a map-space direction; prefetches its radiance and pdf.
  EnvPixel locate(Vec3 direction) const;
  float pdf(const EnvPixel& p) const { return cell(p.x, p.y).pdf_factor / p.sin_theta; }
  Rgb radiance(const EnvPixel& p) const { return map_.image().at(p.x, p.y); }

 private:
  struct Cell {
    float cdf;         // the row's CDF at the cell's left edge (width + 1 per row, the last is 1)
    float pdf_factor;  // p(u, v) / (2 pi^2): the solid-angle pdf times sin(theta)
  };
  const Cell& cell(int x, int y) const { return cells_[size_t(y) * (width_ + 1) + size_t(x)]; }
  static int find(const float* cdf, size_t stride, const uint32_t* guide, int guide_size, float u);

  const EnvMap& map_;
  int width_, height_, row_guide_, marginal_guide_;
  std::vector<float> marginal_cdf_;
  std::vector<uint32_t> marginal_guide_table_, row_guide_table_;
  std::vector<Cell> cells_;
};

}  // namespace lp::render

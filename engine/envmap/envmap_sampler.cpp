#include "engine/envmap/envmap_sampler.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <string>

#include "engine/core/fast_sincos.hpp"

namespace lp {
namespace {

// Pixel weights: luminance * sin(theta of the row centre), so that p(u, v) is proportional to the
// radiance per solid angle.
float row_factor(int y, int height) {
  return float(std::sin(latlong::row_centre_theta(y, height)));
}

PiecewiseConstant2D::RowFiller sampling_weights(const Image& image, LuminanceMode mode, float offset) {
  return [&image, mode, offset](int y, float* out) {
    const float s = row_factor(y, image.height());
    const float* row = image.row(y);
    for (int x = 0; x < image.width(); ++x)
      out[x] = std::max(0.0f, luminance({row[3 * x], row[3 * x + 1], row[3 * x + 2]}, mode) - offset) * s;
  };
}

float compensation_offset(const EnvMap& map, LuminanceMode mode, SamplerWeights weights) {
  if (weights != SamplerWeights::MisCompensated) return 0;
  const float mean = luminance(map.mean_radiance(), mode);
  return map.max_luminance(mode) > mean ? mean : 0;
}

}  // namespace

EnvMapSampler::EnvMapSampler(const EnvMap& map, LuminanceMode mode, SamplerWeights weights)
    : map_(map),
      mode_(mode),
      offset_(compensation_offset(map, mode, weights)),
      dist_(map.width(), map.height(), sampling_weights(map.image(), mode, offset_)) {}

double EnvMapSampler::row_mean_luminance(int y) const {
  return dist_.row_weight_sums()[size_t(y)] / (double(dist_.width()) * row_factor(y, dist_.height()));
}

EnvSample EnvMapSampler::finish(const GridSample& g) const {
  EnvSample s;
  s.pixel_x = g.x;
  s.pixel_y = g.y;
  s.u = float(g.u);
  s.v = float(g.v);
  s.theta = float(g.v * kPi);
  s.phi = float(g.u * 2.0 * kPi);
  const SinCos theta = sincos_turns(float(0.5 * g.v));
  s.direction = latlong::direction(theta, sincos_turns(float(g.u)));
  s.pdf = solid_angle_pdf(g.density, theta.sin);
  s.radiance = map_.image().at(g.x, g.y);
  return s;
}

EnvSample EnvMapSampler::sample(float u1, float u2) const {
  return finish(dist_.sample(u1, u2));
}

std::shared_ptr<const AliasTable2D> EnvMapSampler::alias_table() const {
  // A compensated sampler that fell back to the plain weights shares the plain one's table.
  const std::string key = std::string("alias:") + enum_name(mode_) + (offset_ > 0 ? ":compensated" : "");
  return map_.derived<AliasTable2D>(key, AliasTable2D::memory_bytes(dist_.width(), dist_.height()),
                                    [&] { return std::make_shared<const AliasTable2D>(dist_); });
}

EnvSample EnvMapSampler::sample_alias(const AliasTable2D& table, uint64_t r_row, uint64_t r_col, float fu,
                                      float fv) const {
  return finish(table.sample(dist_, r_row, r_col, fu, fv));
}

void EnvMapSampler::sample_alias(const AliasTable2D& table, std::span<const AliasBits> bits,
                                 std::span<EnvSample> out) const {
  constexpr size_t kBlock = 32;
  AliasTable2D::Cell cells[kBlock];
  for (size_t start = 0; start < bits.size(); start += kBlock) {
    const size_t n = std::min(kBlock, bits.size() - start);
    for (size_t k = 0; k < n; ++k)
      __builtin_prefetch(table.column_entry_address(bits[start + k].r_row, bits[start + k].r_col));
    for (size_t k = 0; k < n; ++k) {
      cells[k] = table.pick(bits[start + k].r_row, bits[start + k].r_col);
      prefetch(cells[k].x, cells[k].y);
    }
    for (size_t k = 0; k < n; ++k) {
      const AliasBits& b = bits[start + k];
      out[start + k] = finish(table.at(dist_, cells[k], b.fu, b.fv));
    }
  }
}

float EnvMapSampler::pdf(Vec3 direction) const {
  const latlong::Uv uv = latlong::uv(direction);
  const int x = latlong::pixel_x(uv.u, dist_.width()), y = latlong::pixel_y(uv.v, dist_.height());
  return pdf(x, y, latlong::sin_theta(direction));
}

}  // namespace lp

#include "engine/mediancut/light_placement.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/envmap/latlong.hpp"

namespace lp {
namespace {

struct RegionSums {
  Power power{};
  double w = 0, wx = 0, wy = 0;  // placement weight and its first moments (pixel-centre coordinates)
};

struct LuminanceWeights {
  double r, g, b;
  double operator()(const double* c) const { return r * c[0] + g * c[1] + b * c[2]; }
};

LuminanceWeights luminance_weights(LuminanceMode mode) {
  if (mode == LuminanceMode::Average) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  return {kRec709Weights.r, kRec709Weights.g, kRec709Weights.b};
}

// Per channel, the sum of a row segment's radiance and of radiance * x (pixel centres). This pass
// over every pixel dominates a large cut, so it works on 4 interleaved RGB pixels (12 floats) at a
// time in vector registers, in double throughout. Luminance is linear, so the centroid's weight
// sums follow from these per-channel sums without a luminance per pixel.
struct RowMoments {
  double sum[3] = {}, sum_x[3] = {};
};

using Float4 = float __attribute__((vector_size(16)));
using Double4 = double __attribute__((vector_size(32)));

template <bool kMoments>
RowMoments row_moments(const float* p, int x0, int x1) {
  // Step k covers pixels x0 + 4k .. x0 + 4k + 3; lane j of the 12 holds pixel x0 + 4k + j/3,
  // channel j%3. s sums the lanes; t sums s after each step, so sum_k k * p_k = steps * s - t
  // (no multiply in the loop).
  Double4 s[3] = {}, t[3] = {};
  const int steps = (x1 - x0) / 4;
  for (int k = 0; k < steps; ++k, p += 12)
    for (int i = 0; i < 3; ++i) {
      Float4 f;
      std::memcpy(&f, p + 4 * i, sizeof f);
      s[i] += __builtin_convertvector(f, Double4);
      if constexpr (kMoments) t[i] += s[i];
    }
  RowMoments m;
  for (int j = 0; j < 12; ++j) {
    const double sj = s[j / 4][j % 4], tj = t[j / 4][j % 4];
    m.sum[j % 3] += sj;
    if constexpr (kMoments) m.sum_x[j % 3] += 4.0 * (steps * sj - tj) + sj * (x0 + j / 3 + 0.5);
  }
  for (int x = x0 + 4 * steps; x < x1; ++x, p += 3)
    for (int c = 0; c < 3; ++c) {
      m.sum[c] += p[c];
      if constexpr (kMoments) m.sum_x[c] += p[c] * (x + 0.5);
    }
  return m;
}

// Power needs L * omega per row; the centroid weight is lum * omega, so per row lum(sum) * omega.
template <bool kMoments>
RegionSums sum_region_linear(const Image& image, const Region& r, const std::vector<double>& omega,
                             LuminanceWeights k) {
  RegionSums s;
  for (int y = r.y0; y < r.y1; ++y) {
    const RowMoments m = row_moments<kMoments>(image.row(y) + 3 * size_t(r.x0), r.x0, r.x1);
    const double o = omega[y];
    for (int c = 0; c < 3; ++c) s.power[c] += m.sum[c] * o;
    if constexpr (kMoments) {
      const double w = k(m.sum) * o;
      s.w += w, s.wx += k(m.sum_x) * o, s.wy += w * (y + 0.5);
    }
  }
  return s;
}

// The centroid weighted by (lum * omega)^2: not linear in the radiance, so a luminance per pixel.
RegionSums sum_region_squared(const Image& image, const Region& r, const std::vector<double>& omega,
                              LuminanceWeights k) {
  RegionSums s;
  for (int y = r.y0; y < r.y1; ++y) {
    const float* p = image.row(y) + 3 * size_t(r.x0);
    double sum[3] = {}, w = 0, wx = 0;
    for (int x = r.x0; x < r.x1; ++x, p += 3) {
      const double c[3] = {p[0], p[1], p[2]};
      const double lum = k(c);
      for (int i = 0; i < 3; ++i) sum[i] += c[i];
      w += lum * lum, wx += lum * lum * (x + 0.5);
    }
    const double o = omega[y], o2 = o * o;
    for (int c = 0; c < 3; ++c) s.power[c] += sum[c] * o;
    s.w += w * o2, s.wx += wx * o2, s.wy += w * o2 * (y + 0.5);
  }
  return s;
}

RegionSums sum_region(const Image& image, const Region& r, const std::vector<double>& omega,
                      LightPlacement placement, LuminanceMode mode) {
  const LuminanceWeights k = luminance_weights(mode);
  switch (placement) {
    case LightPlacement::Centroid:
      return sum_region_linear<true>(image, r, omega, k);
    case LightPlacement::CentroidSquared:
      return sum_region_squared(image, r, omega, k);
    case LightPlacement::Center:
      break;
  }
  return sum_region_linear<false>(image, r, omega, k);
}

}  // namespace

double power_luminance(const Power& p, LuminanceMode mode) {
  return mode == LuminanceMode::Average ? (p[0] + p[1] + p[2]) / 3.0 : luminance_weights(mode)(p.data());
}

std::vector<MedianCutLight> place_lights(const Image& image, const std::vector<Region>& regions,
                                         LightPlacement placement, LuminanceMode mode) {
  const int width = image.width(), height = image.height();
  std::vector<double> omega(height);
  for (int y = 0; y < height; ++y) omega[y] = latlong::pixel_solid_angle(y, width, height);

  std::vector<MedianCutLight> lights(regions.size());
  tbb::parallel_for(size_t{0}, regions.size(), [&](size_t i) {
    const Region& r = regions[i];
    const RegionSums s = sum_region(image, r, omega, placement, mode);
    // A region without energy has no centroid: its light sits at the centre (and carries nothing).
    double px = 0.5 * (r.x0 + r.x1), py = 0.5 * (r.y0 + r.y1);
    if (placement != LightPlacement::Center && s.w > 0) px = s.wx / s.w, py = s.wy / s.w;
    MedianCutLight& light = lights[i];
    light.region = r;
    light.power = s.power;
    light.energy = power_luminance(s.power, mode);
    light.u = px / width, light.v = py / height;
    light.pixel_x = std::clamp(int(std::floor(px)), r.x0, r.x1 - 1);
    light.pixel_y = std::clamp(int(std::floor(py)), r.y0, r.y1 - 1);
    light.direction = latlong::direction({float(light.u), float(light.v)});
  });
  return lights;
}

}  // namespace lp

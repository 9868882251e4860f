#include "engine/render/env_importance.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"

namespace lp::render {
namespace {

// The normalised CDF of n non-negative weights, written to out[i * stride] for i = 0 .. n; uniform
// if they are all zero.
void build_cdf(const double* w, int n, float* out, size_t stride) {
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += w[i];
  double run = 0;
  out[0] = 0;
  for (int i = 0; i < n; ++i) {
    run += w[i];
    out[size_t(i + 1) * stride] = sum > 0 ? float(run / sum) : float(i + 1) / float(n);
  }
  out[size_t(n) * stride] = 1.0f;
}

// guide[j] = the cell containing j / g: the largest i < n with cdf[i] <= j / g (g + 1 entries).
void build_guide(const float* cdf, size_t stride, int n, int g, uint32_t* guide) {
  int i = 0;
  for (int j = 0; j <= g; ++j) {
    const float u = float(j) / float(g);
    while (i < n - 1 && cdf[size_t(i + 1) * stride] <= u) ++i;
    guide[j] = uint32_t(i);
  }
}

}  // namespace

EnvImportance::EnvImportance(const EnvMapSampler& sampler)
    : map_(sampler.map()),
      width_(sampler.distribution().width()),
      height_(sampler.distribution().height()),
      row_guide_(std::max(1, width_ / 4)),
      marginal_guide_(std::max(1, height_ / 2)) {
  const PiecewiseConstant2D& dist = sampler.distribution();
  constexpr size_t kStride = sizeof(Cell) / sizeof(float);
  std::vector<double> row(static_cast<size_t>(width_)), row_sums(static_cast<size_t>(height_));
  cells_.resize(size_t(height_) * (width_ + 1));
  row_guide_table_.resize(size_t(height_) * (row_guide_ + 1));
  const float to_solid_angle = 1.0f / (2.0f * kPiF * kPiF);
  for (int y = 0; y < height_; ++y) {
    Cell* cells = &cells_[size_t(y) * (width_ + 1)];
    double sum = 0;
    for (int x = 0; x < width_; ++x) {
      sum += row[x] = dist.density(x, y);
      cells[x].pdf_factor = dist.density(x, y) * to_solid_angle;
    }
    cells[width_].pdf_factor = 0;
    row_sums[y] = sum;
    build_cdf(row.data(), width_, &cells[0].cdf, kStride);
    build_guide(&cells[0].cdf, kStride, width_, row_guide_, &row_guide_table_[size_t(y) * (row_guide_ + 1)]);
  }
  marginal_cdf_.resize(size_t(height_) + 1);
  build_cdf(row_sums.data(), height_, marginal_cdf_.data(), 1);
  marginal_guide_table_.resize(size_t(marginal_guide_) + 1);
  build_guide(marginal_cdf_.data(), 1, height_, marginal_guide_, marginal_guide_table_.data());
}

int64_t EnvImportance::memory_bytes(int64_t width, int64_t height) {
  const int64_t row_guide = std::max<int64_t>(1, width / 4),
                marginal_guide = std::max<int64_t>(1, height / 2);
  return height * (width + 1) * int64_t(sizeof(Cell)) + height * (row_guide + 1) * int64_t(sizeof(uint32_t)) +
         (height + 1) * int64_t(sizeof(float)) + (marginal_guide + 1) * int64_t(sizeof(uint32_t));
}

std::shared_ptr<const EnvImportance> EnvImportance::of(const EnvMap& map) {
  const int64_t bytes = memory_bytes(map.width(), map.height());
  return map.derived<EnvImportance>("render:env_importance", bytes, [&] {
    return std::make_shared<const EnvImportance>(*map.sampler(LuminanceMode::Average));
  });
}

// The cell i with cdf[i] <= u < cdf[i + 1] (skipping empty cells), searched between two guides.
int EnvImportance::find(const float* cdf, size_t stride, const uint32_t* guide, int guide_size, float u) {
  const int j = std::min(int(u * float(guide_size)), guide_size - 1);
  int lo = int(guide[j]), hi = int(guide[j + 1]);  // the answer is in [lo, hi]
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (cdf[size_t(mid) * stride] <= u) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

ImportanceSample EnvImportance::sample(float u1, float u2) const {
  constexpr size_t kStride = sizeof(Cell) / sizeof(float);
  const int y = find(marginal_cdf_.data(), 1, marginal_guide_table_.data(), marginal_guide_, u2);
  const Cell* row = &cells_[size_t(y) * (width_ + 1)];
  const int x = find(&row[0].cdf, kStride, &row_guide_table_[size_t(y) * (row_guide_ + 1)], row_guide_, u1);
  // Offsets within the cell by linear inversion, in double so that u and v stay inside the cell.
  const double dv = (double(u2) - marginal_cdf_[y]) / (double(marginal_cdf_[y + 1]) - marginal_cdf_[y]);
  const double du = (double(u1) - row[x].cdf) / (double(row[x + 1].cdf) - row[x].cdf);
  const auto u = float((x + std::clamp(du, 0.0, double(kOneMinusEpsilon))) / width_);
  const auto v = float((y + std::clamp(dv, 0.0, double(kOneMinusEpsilon))) / height_);
  // latlong::direction, keeping sin(theta) for the pdf.
  const float sin_theta = std::sin(v * kPiF), cos_theta = std::cos(v * kPiF), phi = u * 2.0f * kPiF;
  ImportanceSample s;
  s.direction = {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
  s.pdf = row[x].pdf_factor / std::max(sin_theta, 1e-7f);
  s.radiance = map_.image().at(x, y);
  return s;
}

EnvPixel EnvImportance::locate(Vec3 direction) const {
  const latlong::Uv uv = latlong::uv(direction);
  // sin(theta) = hypot(x, y) / |d|, the same value as sin(uv.v * pi) without another sine.
  const float sin_theta = std::sqrt(direction.x * direction.x + direction.y * direction.y) / length(direction);
  EnvPixel p{latlong::pixel_x(uv.u, width_), latlong::pixel_y(uv.v, height_), std::max(sin_theta, 1e-7f)};
  __builtin_prefetch(&cell(p.x, p.y));
  __builtin_prefetch(map_.image().row(p.y) + 3 * p.x);
  return p;
}

}  // namespace lp::render

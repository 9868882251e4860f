#include "engine/texture/mip_pyramid.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace lp {
namespace {

// The input texels output texel `i` of `out` covers along an axis of `in` texels, with their weights.
struct Footprint {
  int first = 0, last = 0;                   // inclusive
  double first_weight = 1, last_weight = 1;  // fractions of the end texels covered; the middle ones are 1
  double scale = 1;                          // 1 / covered width, so that the weights sum to 1
};

Footprint footprint(int i, int in, int out) {
  const double ratio = double(in) / out;
  const double start = i * ratio, end = (i + 1) * ratio;
  Footprint f;
  f.first = int(std::floor(start));
  f.last = std::min(in - 1, int(std::ceil(end)) - 1);
  f.first_weight = std::min(end, f.first + 1.0) - start;
  f.last_weight = f.first == f.last ? f.first_weight : end - f.last;
  f.scale = 1.0 / ratio;
  return f;
}

double weight(const Footprint& f, int k) {
  return k == f.first ? f.first_weight : (k == f.last ? f.last_weight : 1.0);
}

// Filters one row of n_in texels into n_out.
void filter_row(const float* in, int n_in, float* out, int n_out, int channels) {
  double sum[4];
  for (int x = 0; x < n_out; ++x) {
    const Footprint f = footprint(x, n_in, n_out);
    std::fill(sum, sum + channels, 0.0);
    for (int k = f.first; k <= f.last; ++k) {
      const float* t = &in[size_t(k) * channels];
      const double w = weight(f, k);
      for (int c = 0; c < channels; ++c) sum[c] += w * t[c];
    }
    for (int c = 0; c < channels; ++c) out[size_t(x) * channels + c] = float(sum[c] * f.scale);
  }
}

}  // namespace

// Each output row filters the input rows it covers along x, then sums them along y: the same
// arithmetic, in the same order, as a pass along x over the whole level and then one along y, without
// the half-size intermediate (rows shared by two output rows, at odd heights, are filtered twice).
MipLevel downsample(int width, int height, int channels, const MipRowSource& row) {
  MipLevel out{std::max(1, width / 2), std::max(1, height / 2), {}};
  out.texels.resize(size_t(out.width) * out.height * channels);
  const size_t out_row = size_t(out.width) * channels;
  tbb::parallel_for(tbb::blocked_range<int>(0, out.height), [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> scratch(size_t(width) * channels), filtered(out_row);
    std::vector<double> sum(out_row);
    for (int y = rows.begin(); y != rows.end(); ++y) {
      std::fill(sum.begin(), sum.end(), 0.0);
      const Footprint f = footprint(y, height, out.height);
      for (int k = f.first; k <= f.last; ++k) {
        filter_row(row(k, scratch.data()), width, filtered.data(), out.width, channels);
        const double w = weight(f, k);
        for (size_t i = 0; i < out_row; ++i) sum[i] += w * filtered[i];
      }
      float* o = &out.texels[size_t(y) * out_row];
      for (size_t i = 0; i < out_row; ++i) o[i] = float(sum[i] * f.scale);
    }
  });
  return out;
}

MipLevel downsample(const MipLevel& level, int channels) {
  return downsample(level.width, level.height, channels,
                    [&](int y, float*) { return &level.texels[size_t(y) * level.width * channels]; });
}

std::vector<MipLevel> build_mip_pyramid(MipLevel base, int channels) {
  std::vector<MipLevel> levels;
  levels.push_back(std::move(base));
  while (levels.back().width > 1 || levels.back().height > 1)
    levels.push_back(downsample(levels.back(), channels));
  return levels;
}

int64_t mip_pyramid_bytes(int64_t width, int64_t height, int channels) {
  int64_t texels = width * height;
  while (width > 1 || height > 1) {
    width = std::max<int64_t>(1, width / 2);
    height = std::max<int64_t>(1, height / 2);
    texels += width * height;
  }
  return texels * channels * int64_t(sizeof(float));
}

}  // namespace lp

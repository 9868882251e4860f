#include "engine/texture/mip_pyramid.hpp"

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

// Filters along x (for each row) or along y (for each column) from `in` into `out`.
void filter_axis(const MipLevel& in, MipLevel& out, int channels, bool along_x) {
  const int n_in = along_x ? in.width : in.height, n_out = along_x ? out.width : out.height;
  tbb::parallel_for(0, out.height, [&](int y) {
    double sum[4];
    for (int x = 0; x < out.width; ++x) {
      const Footprint f = footprint(along_x ? x : y, n_in, n_out);
      std::fill(sum, sum + channels, 0.0);
      for (int k = f.first; k <= f.last; ++k) {
        const float* t = &in.texels[(size_t(along_x ? y : k) * in.width + (along_x ? k : x)) * channels];
        const double w = weight(f, k);
        for (int c = 0; c < channels; ++c) sum[c] += w * t[c];
      }
      float* o = &out.texels[(size_t(y) * out.width + x) * channels];
      for (int c = 0; c < channels; ++c) o[c] = float(sum[c] * f.scale);
    }
  });
}

}  // namespace

MipLevel downsample(const MipLevel& level, int channels) {
  MipLevel rows{std::max(1, level.width / 2), level.height, {}};
  rows.texels.resize(size_t(rows.width) * rows.height * channels);
  filter_axis(level, rows, channels, true);
  MipLevel out{rows.width, std::max(1, level.height / 2), {}};
  out.texels.resize(size_t(out.width) * out.height * channels);
  filter_axis(rows, out, channels, false);
  return out;
}

std::vector<MipLevel> build_mip_pyramid(MipLevel base, int channels) {
  std::vector<MipLevel> levels;
  levels.push_back(std::move(base));
  while (levels.back().width > 1 || levels.back().height > 1)
    levels.push_back(downsample(levels.back(), channels));
  return levels;
}

}  // namespace lp

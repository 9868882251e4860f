#include "engine/sh/row_harmonics.hpp"

#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {
namespace {

// Harmonics are summed a few at a time so that their accumulators (3 channels each) and the pixel
// values stay in registers.
constexpr int kGroup = 3;

}  // namespace

RowHarmonics::RowHarmonics(int width, int bands) : width_(width), harmonics_(2 * bands - 1) {
  const int padded = (harmonics_ + kGroup - 1) / kGroup * kGroup;  // zero harmonics fill the last group
  values_.assign(size_t(padded), std::vector<Pair>(size_t(width + 1) / 2, Pair{0, 0}));
  for (int x = 0; x < width; ++x) {
    const double phi = 2 * kPi * (x + 0.5) / width;
    for (int m = 0; m < bands; ++m) {
      values_[size_t(cos_index(m))][size_t(x / 2)][x % 2] = std::cos(m * phi);
      if (m > 0) values_[size_t(sin_index(m))][size_t(x / 2)][x % 2] = std::sin(m * phi);
    }
  }
}

std::vector<std::array<double, 3>> RowHarmonics::sums(const float* rgb_row) const {
  const size_t pairs = size_t(width_ + 1) / 2;
  std::vector<std::array<Pair, 3>> pixels(pairs);
  for (int x = 0; x < width_; ++x)
    for (int c = 0; c < 3; ++c) pixels[size_t(x / 2)][c][x % 2] = double(rgb_row[3 * x + c]);
  if (width_ % 2 == 1)
    for (int c = 0; c < 3; ++c) pixels.back()[c][1] = 0;
  std::vector<std::array<double, 3>> out(values_.size());  // the padding's sums are 0, dropped below
  for (size_t h0 = 0; h0 < values_.size(); h0 += kGroup) {
    Pair acc[kGroup][3] = {};
    for (size_t i = 0; i < pairs; ++i)
      for (int j = 0; j < kGroup; ++j) {
        const Pair t = values_[h0 + size_t(j)][i];
        for (int c = 0; c < 3; ++c) acc[j][c] += pixels[i][c] * t;
      }
    for (int j = 0; j < kGroup; ++j)
      for (int c = 0; c < 3; ++c) out[h0 + size_t(j)][c] = acc[j][c][0] + acc[j][c][1];
  }
  out.resize(size_t(harmonics_));
  return out;
}

}  // namespace lp

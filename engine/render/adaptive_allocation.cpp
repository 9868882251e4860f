#include "engine/render/adaptive_allocation.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace lp::render {
namespace {

__extension__ typedef unsigned __int128 Sum;

// Weights in fixed point (units of 2^-16, saturating at 2^40), so that sums are exact.
uint64_t fixed_point(float weight) {
  if (!(weight > 0)) return 0;
  return uint64_t(std::min(double(weight), 0x1p40) * 0x1p16);
}

// The largest and the second largest weight around one pixel (itself left out), and where the
// largest is: without pixel `argmax` the weight is `second`, without any other pixel `first`.
struct Neighbourhood {
  uint64_t first = 0, second = 0;
  int64_t argmax = -1;
};

template <class Visit>
void for_each_neighbour(int x, int y, int width, int height, Visit&& visit) {
  for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
    for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
      if (nx != x || ny != y) visit(int64_t(ny) * width + nx);
}

std::vector<Neighbourhood> neighbourhoods(const std::vector<uint64_t>& q, int width, int height) {
  std::vector<Neighbourhood> out(q.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Neighbourhood& n = out[size_t(y) * size_t(width) + size_t(x)];
      for_each_neighbour(x, y, width, height, [&](int64_t j) {
        const uint64_t v = q[size_t(j)];
        if (n.argmax < 0 || v > n.first) {
          n.second = n.first;
          n.first = v;
          n.argmax = j;
        } else {
          n.second = std::max(n.second, v);
        }
      });
    }
  return out;
}

}  // namespace

std::vector<float> allocation_weights(std::span<const float> sigma, std::span<const float> cost) {
  if (sigma.size() != cost.size())
    throw Error(ErrorKind::InvalidArgument, "allocation_weights: the deviations and costs differ in size");
  std::vector<float> w(sigma.size());
  for (size_t i = 0; i < w.size(); ++i) w[i] = sigma[i] / std::sqrt(std::max(cost[i], 1.0f));
  return w;
}

int adaptive_warmup_spp(int spp) {
  return std::min(spp, std::max(spp / 4, 2));
}

std::vector<uint32_t> allocate_samples(std::span<const float> weight, int width, int height, uint64_t budget,
                                       uint64_t seed, uint32_t pass, const AdaptiveRule& rule) {
  const size_t pixels = size_t(width) * size_t(height);
  if (width < 1 || height < 1 || weight.size() != pixels)
    throw Error(ErrorKind::InvalidArgument, "allocate_samples: the weights do not match the image");
  std::vector<uint64_t> q(pixels);
  for (size_t i = 0; i < pixels; ++i) q[i] = fixed_point(weight[i]);
  const std::vector<Neighbourhood> hood = neighbourhoods(q, width, height);
  Sum total = 0;
  for (const Neighbourhood& n : hood) total += n.first;

  const double mean = double(budget) / double(pixels);
  const double cap = rule.cap * mean;
  const uint64_t stream = mix64(seed ^ 0x6a09e667f3bcc908ULL) ^ pass;
  std::vector<uint32_t> counts(pixels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int64_t i = int64_t(y) * width + x;
      Sum without_i = total;  // the total as if pixel i had weight 0
      for_each_neighbour(x, y, width, height, [&](int64_t k) {
        const Neighbourhood& n = hood[size_t(k)];
        if (n.argmax == i) without_i -= n.first - n.second;
      });
      double n = mean;
      if (without_i > 0)
        n = double(budget) * ((1 - rule.uniform_share) * double(hood[size_t(i)].first) / double(without_i) +
                              rule.uniform_share / double(pixels));
      n = std::min(n, cap);
      const double whole = std::floor(n);
      Rng rng(stream, uint64_t(i));
      counts[size_t(i)] = uint32_t(whole) + (rng.uniform_double() < n - whole ? 1u : 0u);
    }
  return counts;
}

}  // namespace lp::render

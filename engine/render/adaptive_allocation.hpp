#pragma once
// How an adaptive pass shares its samples among pixels. The relative RMSE of an image sums the pixels'
// variances sigma_i^2 / n_i, where sigma_i is the standard deviation of one sample of pixel i. A sample
// of pixel i costs c_i (its rays: a pixel of glass or of a glossy wall traces longer paths than one of
// the ground), so for a fixed time sum_i c_i n_i the error is smallest with n_i proportional to
// sigma_i / sqrt(c_i): a fixed count sum_i n_i would take n_i proportional to sigma_i, which spends the
// time on costly pixels where it buys the least.
//
// A pixel's mean over n of its samples is unbiased only if n does not depend on those samples: a pixel
// that drew a bright sample would otherwise get more samples and be pulled back down. So no pixel's
// count reads its own samples: a pixel's weight sigma / sqrt(c) is its own, but pixel i's share s_i is
// the largest weight among the 3 x 3 pixels around it, itself left out. The deviations and costs come
// from a uniform warm-up, the same number of samples in every pixel, so a neighbour's weight does not
// depend on pixel i's samples through the neighbour's own count either.
//
// Pixel i's count is min(a + k s_i, C): an even part a of the mean, at most the cap C, and the scale k
// at which the counts sum to the budget (water-filling: what a capped pixel cannot take goes to the
// others, so a few very noisy neighbourhoods do not leave part of the budget unspent). k depends on
// every share, so pixel i's is the k of the shares as if pixel i had weight 0 (only the shares of the
// up to 8 neighbours whose largest weight is pixel i's change), found exactly in fixed point so that
// not even a rounding of it depends on pixel i. Leaving a weight out can only lower shares and so
// raise k: the counts sum to slightly more than the budget, by a few pixels' mean count in all (at
// most 6.4 measured on synthetic weights; 0.010% to 0.024% of the budget at 64 x 64 on heavy-tailed
// ones, where the tests' bound is 0.05%).
#include <cstdint>
#include <span>
#include <vector>

namespace lp::render {

struct AdaptiveRule {
  // The part of a pass's budget spread evenly over the pixels: a floor for pixels whose neighbours'
  // warm-up missed a rare bright path.
  double uniform_share = 0.2;
  // No pixel gets more than `cap` times the pass's mean samples per pixel (in [1, 1024]).
  double cap = 32;
};

// The uniform warm-up of an adaptive render of `spp` samples per pixel on average: a quarter of them,
// at least 2 (a deviation needs them) and at most `spp`. A warm-up capped at 16 starved pixels whose
// bright paths are rarer than 1 in 16: on the materials preset at 256 spp (64 x 64, forest.exr) it cut
// the squared error by 8%, a quarter by 63%.
int adaptive_warmup_spp(int spp);

// Each pixel's weight: its deviation `sigma` over the square root of its `cost`, the rays one of its
// samples traced on average (at least 1: every sample traces its camera ray).
std::vector<float> allocation_weights(std::span<const float> sigma, std::span<const float> cost);

// The samples each pixel (row-major, width x height) is to draw on average in an adaptive pass of
// `budget` samples in all, given every pixel's `weight` (allocation_weights); when no neighbourhood has
// any weight every pixel gets the mean.
std::vector<double> expected_samples(std::span<const float> weight, int width, int height, uint64_t budget,
                                     const AdaptiveRule& rule = {});

// expected_samples rounded stochastically, by a hash of (seed, pass, pixel), to whole samples.
std::vector<uint32_t> allocate_samples(std::span<const float> weight, int width, int height, uint64_t budget,
                                       uint64_t seed, uint32_t pass, const AdaptiveRule& rule = {});

}  // namespace lp::render

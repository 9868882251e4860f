#pragma once
// Per-pixel accumulation over passes: a pass writes its per-pixel sums into a staging buffer (tiles own
// disjoint pixels, so no locking), and only a finished pass is merged into the running totals.
// image() may be called from another thread while a pass renders.
//
// Each pixel has its own count of samples: a uniform pass adds the same number to every pixel, an
// adaptive pass a number of its own to each (adaptive_allocation.hpp). A pixel's samples are always
// the indices 0, 1, 2, ... of its sequence, so its mean is over a prefix of it. While every pass has
// been uniform the film also sums each pixel's squared samples and the rays its samples traced, from
// which the first adaptive pass takes the pixels' deviations and costs (kept from then on, the same
// for every later adaptive pass).
//
// The auxiliary passes a render asks for (scene_desc.hpp, AuxPass) are summed beside the colour, with the
// same samples and counts; a film without them holds none of their memory.
#include <algorithm>
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

class Film {
 public:
  Film(int width, int height, PassSet passes = {});
  // The bytes a film of width x height pixels holds, with an adaptive pass's counts.
  static int64_t memory_bytes(int64_t width, int64_t height, const PassSet& passes = {}) {
    return width * height *
           ((3 + passes.channels()) * int64_t(sizeof(float) + sizeof(double)) +
            int64_t(sizeof(float) + sizeof(double)) + int64_t(sizeof(uint32_t) + sizeof(uint64_t)) +
            2 * int64_t(sizeof(uint32_t)) + 2 * int64_t(sizeof(float)));
  }

  int width() const { return width_; }
  int height() const { return height_; }
  const PassSet& passes() const { return passes_; }

  // The samples of pixel (x, y) so far: the index its next sample draws.
  uint32_t count(int x, int y) const { return count_[size_t(y) * size_t(width_) + size_t(x)]; }

  // The staging sum of the current pass's samples of one pixel, of their squared channels, and the
  // rays they traced.
  void set_pass_sum(int x, int y, Rgb sum, float sum_squares, uint32_t rays) {
    const size_t i = size_t(y) * size_t(width_) + size_t(x);
    float* p = &pass_[i * 3];
    p[0] = sum.x, p[1] = sum.y, p[2] = sum.z;
    pass_squares_[i] = sum_squares;
    pass_rays_[i] = rays;
  }
  // The staging sums of the auxiliary channels of one pixel (passes().channels() values).
  void set_pass_aux(int x, int y, const float* sums) {
    const size_t n = size_t(passes_.channels()), i = (size_t(y) * size_t(width_) + size_t(x)) * n;
    std::copy(sums, sums + n, aux_pass_.data() + i);
  }
  // Adds the staged pass of `spp` samples per pixel to the totals.
  void merge_pass(int spp);
  // Adds the staged pass of counts[i] samples of pixel i (row-major) to the totals.
  void merge_pass(std::span<const uint32_t> counts);
  // Replaces the totals with those of an earlier run: its mean image over `spp` samples per pixel.
  // Its deviations are unknown, so adaptive passes are refused afterwards.
  void restore(const Image& mean, int spp);
  // The same for auxiliary pass p (which the film holds), after restore().
  void restore(AuxPass p, const Image& mean);

  // Whether deviations() can be had: no restore(), and at least 2 samples per pixel if every pass was
  // uniform.
  bool has_deviations() const;
  // Whether restore() set the totals (an earlier run's mean, without its deviations).
  bool restored() const { return restored_; }
  // Each pixel's standard deviation of one sample (over its channels, sqrt of the summed variances),
  // from the uniform passes before the first call; the same from then on. Call between passes.
  std::span<const float> deviations();
  // Each pixel's rays per sample over the same passes, the cost of one more of its samples.
  std::span<const float> costs();

  int spp() const;  // samples per pixel: the mean count, rounded to the nearest
  uint64_t samples() const;
  Image mean() const;
  // The mean of auxiliary pass p (which the film holds), as aux_passes.hpp's aux_mean gives it.
  Image mean(AuxPass p) const;

 private:
  void merge_aux();  // with the lock held

  int width_, height_;
  PassSet passes_;
  std::vector<float> pass_, pass_squares_, aux_pass_;
  std::vector<uint32_t> pass_rays_;
  std::vector<double> squares_;  // sums of squared channels while every pass is uniform
  std::vector<uint64_t> rays_;   // and of rays
  std::vector<float> deviation_, cost_;
  bool restored_ = false;
  mutable std::mutex mutex_;  // guards total_, count_ and samples_
  std::vector<double> total_, aux_total_;
  std::vector<uint32_t> count_;
  uint64_t samples_ = 0;
};

}  // namespace lp::render

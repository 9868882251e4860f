#pragma once
// Per-pixel accumulation over passes: a pass writes its per-pixel sums into a staging buffer (tiles own
// disjoint pixels, so no locking), and only a finished pass is merged into the running totals.
// image() may be called from another thread while a pass renders.
#include <cstdint>
#include <mutex>
#include <vector>

#include "engine/image/image.hpp"

namespace lp::render {

class Film {
 public:
  Film(int width, int height);
  // The bytes a film of width x height pixels holds.
  static int64_t memory_bytes(int64_t width, int64_t height) {
    return width * height * 3 * int64_t(sizeof(float) + sizeof(double));
  }

  int width() const { return width_; }
  int height() const { return height_; }

  // The staging sum of `spp` samples of one pixel in the current pass.
  void set_pass_sum(int x, int y, Rgb sum) {
    float* p = &pass_[(size_t(y) * width_ + x) * 3];
    p[0] = sum.x, p[1] = sum.y, p[2] = sum.z;
  }
  // Adds the staged pass (of `spp` samples per pixel) to the totals.
  void merge_pass(int spp);
  // Replaces the totals with those of an earlier run: its mean image over `spp` samples per pixel.
  void restore(const Image& mean, int spp);

  int spp() const;
  Image mean() const;

 private:
  int width_, height_;
  std::vector<float> pass_;
  mutable std::mutex mutex_;  // guards total_ and spp_
  std::vector<double> total_;
  int spp_ = 0;
};

}  // namespace lp::render

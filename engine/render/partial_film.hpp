#pragma once
// The samples of a range [first, end) of a render's per-pixel sample indices: per pixel the linear RGB sum
// and the count of samples, never tone mapped. Partials of disjoint ranges merge exactly (sum of sums, sum
// of counts, in double), so merging the ranges of a render in any order gives the image one process
// renders, within float rounding. A render split over machines sends these. The auxiliary passes of the
// render (scene_desc.hpp, AuxPass) travel beside the colour, summed and merged alike.
#include <cstdint>
#include <vector>

#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct SampleRange {
  uint32_t first = 0, end = 0;  // sample indices [first, end)
  int count() const { return int(end - first); }
  bool operator==(const SampleRange&) const = default;
};

// The ranges of at most `per_item` samples that cover [0, spp) outside `done` (disjoint ranges, in any
// order), in order.
std::vector<SampleRange> ranges_outside(int spp, int per_item, std::vector<SampleRange> done);

class PartialFilm {
 public:
  PartialFilm() = default;
  PartialFilm(int width, int height, PassSet passes = {});
  // The film of `count` samples per pixel whose mean is `mean` (a render continued from its image), with
  // room for `passes` (set_mean).
  static PartialFilm from_mean(const Image& mean, uint32_t count, PassSet passes = {});
  // The bytes a partial of width x height pixels holds.
  static int64_t memory_bytes(int64_t width, int64_t height, const PassSet& passes = {}) {
    return width * height * int64_t((3 + size_t(passes.channels())) * sizeof(double) + sizeof(uint32_t));
  }

  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixel_count() const { return counts_.size(); }
  const PassSet& passes() const { return passes_; }
  size_t aux_channels() const { return size_t(passes_.channels()); }

  // The sum of `count` samples of pixel (x, y), added to what the pixel holds.
  void add(int x, int y, Rgb sum, uint32_t count) { add(size_t(y) * size_t(width_) + size_t(x), sum, count); }
  void add(size_t pixel, Rgb sum, uint32_t count) {
    double* s = &sums_[pixel * 3];
    s[0] += sum.x, s[1] += sum.y, s[2] += sum.z;
    counts_[pixel] += count;
  }
  // The same with the sums of the auxiliary channels (aux_channels() of them).
  void add(size_t pixel, Rgb sum, uint32_t count, const float* aux) {
    add(pixel, sum, count);
    const size_t n = aux_channels();
    for (size_t c = 0; c < n; ++c) aux_[pixel * n + c] += aux[c];
  }
  // Sets auxiliary pass p (which the film holds) to `mean` over each pixel's count (a render continued
  // from its images).
  void set_mean(AuxPass p, const Image& mean);
  // Adds another partial of the same size (throws lp::Error InvalidArgument otherwise).
  void merge(const PartialFilm& other);

  Rgb sum(size_t pixel) const {
    return {float(sums_[pixel * 3]), float(sums_[pixel * 3 + 1]), float(sums_[pixel * 3 + 2])};
  }
  const double* sums() const { return sums_.data(); }
  const double* aux(size_t pixel) const { return aux_.data() + pixel * aux_channels(); }
  uint32_t count(size_t pixel) const { return counts_[pixel]; }
  // The mean of every pixel (black where no sample arrived yet).
  Image mean() const;
  Image mean(AuxPass p) const;

 private:
  int width_ = 0, height_ = 0;
  PassSet passes_;
  std::vector<double> sums_, aux_;
  std::vector<uint32_t> counts_;
};

}  // namespace lp::render

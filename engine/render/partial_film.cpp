#include "engine/render/partial_film.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/render/aux_passes.hpp"

namespace lp::render {

PartialFilm::PartialFilm(int width, int height, PassSet passes)
    : width_(width),
      height_(height),
      passes_(passes),
      sums_(size_t(width) * size_t(height) * 3),
      aux_(size_t(width) * size_t(height) * size_t(passes.channels())),
      counts_(size_t(width) * size_t(height)) {}

std::vector<SampleRange> ranges_outside(int spp, int per_item, std::vector<SampleRange> done) {
  std::sort(done.begin(), done.end(), [](auto a, auto b) { return a.first < b.first; });
  std::vector<SampleRange> out;
  auto cover = [&](uint32_t from, uint32_t to) {
    for (uint32_t first = from; first < to; first += uint32_t(per_item))
      out.push_back({first, std::min(to, first + uint32_t(per_item))});
  };
  uint32_t next = 0;
  for (const auto& d : done) {
    cover(next, std::min(d.first, uint32_t(spp)));
    next = std::max(next, d.end);
  }
  cover(next, uint32_t(spp));
  return out;
}

PartialFilm PartialFilm::from_mean(const Image& mean, uint32_t count, PassSet passes) {
  PartialFilm film(mean.width(), mean.height(), passes);
  const auto pixels = mean.data();
  for (size_t i = 0; i < film.sums_.size(); ++i) film.sums_[i] = double(pixels[i]) * count;
  std::fill(film.counts_.begin(), film.counts_.end(), count);
  return film;
}

void PartialFilm::merge(const PartialFilm& other) {
  if (other.width_ != width_ || other.height_ != height_ || other.passes_ != passes_)
    throw Error(ErrorKind::InvalidArgument, "partial film: merging partials of different sizes or passes");
  for (size_t i = 0; i < sums_.size(); ++i) sums_[i] += other.sums_[i];
  for (size_t i = 0; i < aux_.size(); ++i) aux_[i] += other.aux_[i];
  for (size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
}

Image PartialFilm::mean() const {
  Image image(width_, height_);
  auto out = image.data();
  for (size_t p = 0; p < counts_.size(); ++p) {
    if (counts_[p] == 0) continue;
    const double inv = 1.0 / counts_[p];
    for (size_t c = 0; c < 3; ++c) out[p * 3 + c] = float(sums_[p * 3 + c] * inv);
  }
  return image;
}

void PartialFilm::set_mean(AuxPass p, const Image& mean) {
  if (!passes_.has(p) || mean.width() != width_ || mean.height() != height_)
    throw Error(ErrorKind::InvalidArgument, "partial film: the pass does not match the film");
  for (size_t i = 0; i < counts_.size(); ++i)
    aux_sums(p, passes_, mean.at(int(i % size_t(width_)), int(i / size_t(width_))), counts_[i],
             aux_.data() + i * aux_channels());
}

Image PartialFilm::mean(AuxPass p) const {
  if (!passes_.has(p)) throw Error(ErrorKind::InvalidArgument, "partial film: no such pass");
  return aux_image(p, passes_, width_, height_, aux_, counts_);
}

}  // namespace lp::render

#include "engine/render/partial_film.hpp"

#include "engine/core/error.hpp"

namespace lp::render {

PartialFilm::PartialFilm(int width, int height)
    : width_(width),
      height_(height),
      sums_(size_t(width) * size_t(height) * 3),
      counts_(size_t(width) * size_t(height)) {}

void PartialFilm::merge(const PartialFilm& other) {
  if (other.width_ != width_ || other.height_ != height_)
    throw Error(ErrorKind::InvalidArgument, "partial film: merging partials of different sizes");
  for (size_t i = 0; i < sums_.size(); ++i) sums_[i] += other.sums_[i];
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

}  // namespace lp::render

#include "engine/render/film.hpp"

#include "engine/core/error.hpp"

namespace lp::render {

Film::Film(int width, int height)
    : width_(width), height_(height), pass_(size_t(width) * height * 3), total_(size_t(width) * height * 3) {}

void Film::merge_pass(int spp) {
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < total_.size(); ++i) total_[i] += pass_[i];
  spp_ += spp;
}

void Film::restore(const Image& mean, int spp) {
  if (mean.width() != width_ || mean.height() != height_ || spp < 0)
    throw Error(ErrorKind::InvalidArgument, "film: the restored image does not match the render's size");
  const auto in = mean.data();
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < total_.size(); ++i) total_[i] = double(in[i]) * spp;
  spp_ = spp;
}

int Film::spp() const {
  std::lock_guard lock(mutex_);
  return spp_;
}

Image Film::mean() const {
  Image image(width_, height_);
  std::lock_guard lock(mutex_);
  if (spp_ == 0) return image;
  const double inv = 1.0 / spp_;
  auto out = image.data();
  for (size_t i = 0; i < total_.size(); ++i) out[i] = float(total_[i] * inv);
  return image;
}

}  // namespace lp::render

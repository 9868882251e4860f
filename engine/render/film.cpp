#include "engine/render/film.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/render/aux_passes.hpp"

namespace lp::render {

Film::Film(int width, int height, PassSet passes)
    : width_(width),
      height_(height),
      passes_(passes),
      pass_(size_t(width) * size_t(height) * 3),
      pass_squares_(size_t(width) * size_t(height)),
      aux_pass_(size_t(width) * size_t(height) * size_t(passes.channels())),
      pass_rays_(size_t(width) * size_t(height)),
      squares_(size_t(width) * size_t(height)),
      rays_(size_t(width) * size_t(height)),
      total_(size_t(width) * size_t(height) * 3),
      aux_total_(aux_pass_.size()),
      count_(size_t(width) * size_t(height)) {}

void Film::merge_pass(int spp) {
  if (deviation_.empty())
    for (size_t i = 0; i < squares_.size(); ++i) {
      squares_[i] += pass_squares_[i];
      rays_[i] += pass_rays_[i];
    }
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < total_.size(); ++i) total_[i] += pass_[i];
  merge_aux();
  for (uint32_t& c : count_) c += uint32_t(spp);
  samples_ += uint64_t(spp) * count_.size();
}

void Film::merge_pass(std::span<const uint32_t> counts) {
  if (counts.size() != count_.size())
    throw Error(ErrorKind::InvalidArgument, "film: the pass's counts do not match the film");
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < total_.size(); ++i) total_[i] += pass_[i];
  merge_aux();
  for (size_t i = 0; i < count_.size(); ++i) {
    count_[i] += counts[i];
    samples_ += counts[i];
  }
}

void Film::restore(const Image& mean, int spp) {
  if (mean.width() != width_ || mean.height() != height_ || spp < 0)
    throw Error(ErrorKind::InvalidArgument, "film: the restored image does not match the render's size");
  const auto in = mean.data();
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < total_.size(); ++i) total_[i] = double(in[i]) * spp;
  for (uint32_t& c : count_) c = uint32_t(spp);
  samples_ = uint64_t(spp) * count_.size();
  restored_ = true;
}

void Film::merge_aux() {
  for (size_t i = 0; i < aux_total_.size(); ++i) aux_total_[i] += aux_pass_[i];
}

void Film::restore(AuxPass p, const Image& mean) {
  if (!passes_.has(p) || mean.width() != width_ || mean.height() != height_)
    throw Error(ErrorKind::InvalidArgument, "film: the restored pass does not match the render");
  const size_t n = size_t(passes_.channels());
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < count_.size(); ++i)
    aux_sums(p, passes_, mean.at(int(i % size_t(width_)), int(i / size_t(width_))), count_[i],
             &aux_total_[i * n]);
}

bool Film::has_deviations() const {
  return !restored_ && (!deviation_.empty() || (!count_.empty() && count_[0] >= 2));
}

std::span<const float> Film::deviations() {
  if (!has_deviations())
    throw Error(ErrorKind::InvalidArgument, "film: no deviations without 2 uniform samples per pixel");
  if (deviation_.empty()) {
    deviation_.resize(count_.size());
    for (size_t i = 0; i < count_.size(); ++i) {
      const double n = count_[i], *sum = &total_[i * 3];
      const double mean_squares = (sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]) / (n * n);
      const double variance = (squares_[i] / n - mean_squares) * n / (n - 1);
      deviation_[i] = float(std::sqrt(std::max(variance, 0.0)));
    }
    cost_.resize(count_.size());
    for (size_t i = 0; i < count_.size(); ++i) cost_[i] = float(double(rays_[i]) / count_[i]);
  }
  return deviation_;
}

std::span<const float> Film::costs() {
  deviations();
  return cost_;
}

int Film::spp() const {
  std::lock_guard lock(mutex_);
  return count_.empty() ? 0 : int((samples_ + count_.size() / 2) / count_.size());
}

uint64_t Film::samples() const {
  std::lock_guard lock(mutex_);
  return samples_;
}

Image Film::mean() const {
  Image image(width_, height_);
  auto out = image.data();
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < count_.size(); ++i) {
    if (count_[i] == 0) continue;
    const double inv = 1.0 / count_[i];
    for (size_t k = i * 3; k < i * 3 + 3; ++k) out[k] = float(total_[k] * inv);
  }
  return image;
}

Image Film::mean(AuxPass p) const {
  if (!passes_.has(p)) throw Error(ErrorKind::InvalidArgument, "film: the render holds no such pass");
  std::lock_guard lock(mutex_);
  return aux_image(p, passes_, width_, height_, aux_total_, count_);
}

}  // namespace lp::render

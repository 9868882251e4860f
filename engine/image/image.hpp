#pragma once
// A linear float RGB image, row 0 at the top, pixels stored row-major as r,g,b.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/vec3.hpp"

namespace lp {

class Image {
 public:
  Image() = default;
  Image(int width, int height);  // all black

  int width() const { return width_; }
  int height() const { return height_; }
  int64_t pixel_count() const { return int64_t{width_} * height_; }
  bool empty() const { return pixel_count() == 0; }

  Rgb at(int x, int y) const {
    const float* p = &data_[index(x, y)];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, Rgb c) {
    float* p = &data_[index(x, y)];
    p[0] = c.x, p[1] = c.y, p[2] = c.z;
  }
  float* row(int y) { return &data_[index(0, y)]; }
  const float* row(int y) const { return &data_[index(0, y)]; }
  std::span<float> data() { return data_; }
  std::span<const float> data() const { return data_; }

 private:
  size_t index(int x, int y) const { return (size_t(y) * size_t(width_) + size_t(x)) * 3; }

  int width_ = 0;
  int height_ = 0;
  std::vector<float> data_;
};

// Nearest-neighbour or box resize (used to make large test and benchmark maps).
Image resize_box(const Image& src, int width, int height);

}  // namespace lp

#pragma once
// The error of an image against a reference of the same size, as denoisers are judged (and bench/ measures
// it): the relative mean squared error over every pixel and channel, (x - r)^2 / (r^2 + 0.01).
#include "engine/image/image.hpp"

namespace lp::test {

inline double rel_mse(const Image& image, const Image& reference) {
  const auto x = image.data(), r = reference.data();
  double sum = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double d = double(x[i]) - double(r[i]);
    sum += d * d / (double(r[i]) * double(r[i]) + 0.01);
  }
  return sum / double(x.size());
}

}  // namespace lp::test

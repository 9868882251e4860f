#pragma once
// A smooth image, the same with the noise of a few samples per pixel, and the relative MSE between
// them: what the denoiser's tests and benchmark feed it and measure it by.
#include <cmath>
#include <random>

#include "engine/image/image.hpp"

namespace lp::test {

// Horizontal and vertical ramps and a slow sine, all in [0.2, 0.8].
inline Image smooth_gradient(int width, int height) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.set(x, y,
              {0.2f + 0.6f * float(x) / float(width), 0.3f + 0.4f * float(y) / float(height),
               0.5f + 0.3f * std::sin(float(x) / 40.f)});
  return img;
}

// Each channel times an exponential variate (mean 1): the spread of a few samples per pixel.
inline Image with_exponential_noise(const Image& clean, unsigned seed) {
  std::mt19937 rng(seed);
  std::exponential_distribution<float> spread(1.f);
  Image img = clean;
  for (float& v : img.data()) v *= spread(rng);
  return img;
}

// Mean of (a - ref)^2 / (ref^2 + 0.01) over every channel.
inline double rel_mse(const Image& a, const Image& reference) {
  double sum = 0;
  for (size_t i = 0; i < a.data().size(); ++i) {
    const double r = reference.data()[i], d = a.data()[i] - r;
    sum += d * d / (r * r + 1e-2);
  }
  return sum / double(a.data().size());
}

}  // namespace lp::test

#include "engine/image/rgbd.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/image.hpp"

namespace lp {

namespace {

// Babylon's Epsilon: the smallest brightness it divides by.
constexpr float kEpsilon = 1e-7f;

float non_negative(float v) {
  return v > 0 ? v : 0;  // NaN compares false
}

uint8_t unorm8(float v) {
  return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

Rgbd8 encode_rgbd(Rgb linear) {
  const Rgb c{non_negative(linear.x), non_negative(linear.y), non_negative(linear.z)};
  const float brightest = std::max(max_component(c), kEpsilon);
  // D = saturate(floor(max(range / brightest, 1)) / 255): a whole number of 255ths, 1 to 255 of them.
  const float d255 = std::clamp(std::floor(std::max(kRgbdMaxRange / brightest, 1.0f)), 1.0f, 255.0f);
  const float d = d255 / 255.0f;
  const auto channel = [&](float v) { return unorm8(std::pow(std::min(v * d, 1.0f), 1.0f / kRgbdGamma)); };
  return {channel(c.x), channel(c.y), channel(c.z), uint8_t(d255)};
}

Rgb decode_rgbd(Rgbd8 rgbd) {
  const float d = std::max(float(rgbd[3]), 1.0f) / 255.0f;  // D = 0 never comes out of encode_rgbd
  const auto channel = [&](uint8_t v) { return std::pow(float(v) / 255.0f, kRgbdGamma) / d; };
  return {channel(rgbd[0]), channel(rgbd[1]), channel(rgbd[2])};
}

std::vector<uint8_t> encode_rgbd_pixels(const Image& image) {
  std::vector<uint8_t> out(size_t(image.pixel_count()) * 4);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgbd8 p = encode_rgbd(image.at(x, y));
      std::copy(p.begin(), p.end(), out.begin() + (ptrdiff_t(y) * image.width() + x) * 4);
    }
  return out;
}

Image decode_rgbd_pixels(std::span<const uint8_t> rgba, int width, int height) {
  if (width <= 0 || height <= 0 || rgba.size() != size_t(width) * size_t(height) * 4)
    throw Error(ErrorKind::InvalidArgument, "RGBD: expected " + std::to_string(width) + "x" +
                                                std::to_string(height) + " pixels of 4 bytes");
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4;
      image.set(x, y, decode_rgbd({rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]}));
    }
  return image;
}

}  // namespace lp

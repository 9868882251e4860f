#include "engine/envmap/invalid_pixels.hpp"

#include <fmt/format.h>

#include <cmath>

#include "engine/core/error.hpp"

namespace lp {
namespace {

bool usable(float v) {
  return std::isfinite(v) && std::abs(v) <= kMaxRadiance;
}

const char* problem(float v) {
  if (std::isnan(v)) return "a NaN value";
  if (std::isinf(v)) return "an infinite value";
  if (!usable(v)) return "a value over the largest radiance accepted";
  return "a negative value";
}

[[noreturn]] void reject(const Image& image, size_t pixel, int channel, float v) {
  const size_t w = size_t(image.width());
  throw Error(
      ErrorKind::InvalidData,
      fmt::format("pixel ({}, {}) has {} ({}) in channel {}; radiance must be finite, non-negative and at "
                  "most {:g} (invalid=clamp loads such maps with negatives clamped to 0 and invalid pixels "
                  "black)",
                  pixel % w, pixel / w, problem(v), v, "RGB"[channel], kMaxRadiance));
}

}  // namespace

InvalidPixelReport sanitize_radiance(Image& image, InvalidPixelPolicy policy) {
  InvalidPixelReport report;
  const auto data = image.data();
  for (size_t i = 0; i < data.size(); i += 3) {
    float* p = &data[i];
    for (int c = 0; c < 3; ++c) {
      if (usable(p[c])) continue;
      if (policy == InvalidPixelPolicy::Reject) reject(image, i / 3, c, p[c]);
      p[0] = p[1] = p[2] = 0.0f;
      ++report.non_finite_pixels;
      break;
    }
    for (int c = 0; c < 3; ++c) {
      if (!(p[c] < 0.0f)) continue;
      if (policy == InvalidPixelPolicy::Reject) reject(image, i / 3, c, p[c]);
      report.most_negative_value = std::min(report.most_negative_value, p[c]);
      p[c] = 0.0f;
      ++report.clamped_negative_values;
    }
  }
  return report;
}

}  // namespace lp

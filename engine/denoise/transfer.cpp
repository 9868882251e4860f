#include "engine/denoise/transfer.hpp"

#include <cmath>

namespace lp::denoise {
namespace {

// OIDN's PU curve (core/color.h): a fit of the perceptually uniform encoding of HDR luminance.
namespace pu {
constexpr float a = 1.41283765e+03f, b = 1.64593172e+00f, c = 4.31384981e-01f, d = -2.94139609e-03f;
constexpr float e = 1.92653254e-01f, f = 6.26026094e-03f, g = 9.98620152e-01f;
constexpr float y0 = 1.57945760e-06f, y1 = 3.22087631e-02f, x0 = 2.23151711e-03f, x1 = 3.70974749e-01f;

float forward(float y) {
  if (y <= y0) return a * y;
  if (y <= y1) return b * std::pow(y, c) + d;
  return e * std::log(y + f) + g;
}
float inverse(float x) {
  if (x <= x0) return x / a;
  if (x <= x1) return std::pow((x - d) / b, 1.f / c);
  return std::exp((x - g) / e) - f;
}
constexpr float kMaxHdr = 65504.f;  // the largest half float: PU maps it to 1 after normalisation
const float kNorm = 1.f / forward(kMaxHdr);
}  // namespace pu

namespace srgb {
constexpr float a = 12.92f, b = 1.055f, c = 1.f / 2.4f, d = -0.055f, y0 = 0.0031308f, x0 = 0.04045f;
float forward(float y) {
  return y <= y0 ? a * y : b * std::pow(y, c) + d;
}
float inverse(float x) {
  return x <= x0 ? x / a : std::pow((x - d) / b, 1.f / c);
}
}  // namespace srgb

constexpr int kBinSize = 16;
constexpr float kKey = 0.18f;
constexpr float kEps = 1e-8f;

float luminance(Rgb c) {
  return 0.212671f * c.x + 0.715160f * c.y + 0.072169f * c.z;
}

}  // namespace

float transfer_forward(Transfer t, float y) {
  return t == Transfer::Pu ? pu::forward(y) * pu::kNorm : srgb::forward(y);
}

float transfer_inverse(Transfer t, float x) {
  return t == Transfer::Pu ? pu::inverse(x / pu::kNorm) : srgb::inverse(x);
}

float autoexposure(const Image& color) {
  const int h = color.height(), w = color.width();
  const int bins_h = (h + kBinSize - 1) / kBinSize, bins_w = (w + kBinSize - 1) / kBinSize;
  double log_sum = 0;
  int count = 0;
  for (int i = 0; i < bins_h; ++i) {
    const int y0 = int(int64_t{i} * h / bins_h), y1 = int(int64_t{i + 1} * h / bins_h);
    for (int j = 0; j < bins_w; ++j) {
      const int x0 = int(int64_t{j} * w / bins_w), x1 = int(int64_t{j + 1} * w / bins_w);
      float sum = 0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          const Rgb c = color.at(x, y);
          sum += luminance(
              {sanitize(c.x, 0, kFloatMax), sanitize(c.y, 0, kFloatMax), sanitize(c.z, 0, kFloatMax)});
        }
      const float mean = sum / float((y1 - y0) * (x1 - x0));
      if (mean > kEps) log_sum += std::log2(mean), ++count;
    }
  }
  const float scale = count > 0 ? kKey / float(std::exp2(log_sum / count)) : 1.f;
  return std::isnormal(scale) ? scale
                              : 1.f;  // not for radiance near the float limits, whose inverse overflows
}

}  // namespace lp::denoise

#include "engine/image/tone/display_encoding.hpp"

#include <cmath>

namespace lp::tone {
namespace {

double srgb_decode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace

DisplayEncoding::DisplayEncoding(std::optional<float> gamma) {
  // Code k covers encoded values in [(k - 0.5) / 255, (k + 0.5) / 255).
  for (size_t k = 1; k < starts_.size(); ++k) {
    const double encoded = (double(k) - 0.5) / 255.0;
    starts_[k] = float(gamma ? std::pow(encoded, double(*gamma)) : srgb_decode(encoded));
  }
  for (size_t bin = 0; bin < kBins; ++bin)
    first_code_[bin] = search(std::bit_cast<float>(uint32_t((kFirstBin + bin) << kMantissaShift)));
}

uint8_t DisplayEncoding::search(float linear) const {
  int code = 0;
  for (int step = 128; step > 0; step >>= 1)
    if (linear >= starts_[size_t(code + step)]) code += step;
  return uint8_t(code);
}

}  // namespace lp::tone

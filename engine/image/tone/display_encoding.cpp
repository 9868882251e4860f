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
}

}  // namespace lp::tone

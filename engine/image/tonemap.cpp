#include "engine/image/tonemap.hpp"

#include <algorithm>
#include <cmath>

namespace lp {

ToneMapper::ToneMapper(const ToneMap& tone)
    : scale_(std::exp2(tone.exposure)), inv_gamma_(tone.gamma ? 1.0f / *tone.gamma : 1.0f), srgb_(!tone.gamma) {}

uint8_t ToneMapper::operator()(float linear) const {
  const float scaled = linear * scale_;
  if (!(scaled > 0.0f)) return 0;  // also NaN
  const float x = std::min(scaled, 1.0f);
  float encoded;
  if (srgb_) encoded = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  else encoded = std::pow(x, inv_gamma_);
  return uint8_t(std::lround(encoded * 255.0f));
}

}  // namespace lp

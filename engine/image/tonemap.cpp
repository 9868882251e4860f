#include "engine/image/tonemap.hpp"

#include <algorithm>
#include <cmath>

#include "engine/image/tone/curves.hpp"

namespace lp {
namespace {

// Beyond this every curve shows white; bounding the input keeps the rational fits clear of overflow.
constexpr float kMaxScaled = 1e6f;

float admissible(float v) {
  return v > 0.0f ? std::min(v, kMaxScaled) : 0.0f;  // also NaN
}

Vec3 curve_of(ToneCurve curve, Vec3 c) {
  switch (curve) {
    case ToneCurve::Standard:
      return c;
    case ToneCurve::Neutral:
      return tone::pbr_neutral(c);
    case ToneCurve::Agx:
      return tone::agx(c);
    case ToneCurve::Aces:
      return tone::aces_hill(c);
    case ToneCurve::Reinhard:
      return tone::reinhard(c);
  }
  return c;
}

}  // namespace

Vec3 apply_tone_curve(ToneCurve curve, Vec3 scaled) {
  const Vec3 out = curve_of(curve, {admissible(scaled.x), admissible(scaled.y), admissible(scaled.z)});
  // Out of the display's range (past white, or out of its gamut for agx and aces): clipped, as three.js.
  return {std::clamp(out.x, 0.0f, 1.0f), std::clamp(out.y, 0.0f, 1.0f), std::clamp(out.z, 0.0f, 1.0f)};
}

ToneMapper::ToneMapper(const ToneMap& tone)
    : scale_(std::exp2(tone.exposure)), curve_(tone.curve), encode_(tone.gamma) {}

void ToneMapper::operator()(const float* rgb, uint8_t* out) const {
  const Vec3 display = apply_tone_curve(curve_, Vec3{rgb[0], rgb[1], rgb[2]} * scale_);
  out[0] = encode_(display.x);
  out[1] = encode_(display.y);
  out[2] = encode_(display.z);
}

}  // namespace lp

#include "api/preview_params.hpp"

#include "api/api_error.hpp"
#include "api/parameters.hpp"

namespace lp::api {

ToneMap parse_tone_map(const Query& q, ToneCurve curve) {
  ToneMap tone;
  tone.curve = query_enum(q, kToneMapping.name, curve);
  const NumberField &e = kExposure, &g = kGamma;
  tone.exposure = float(query_double(q, e.name, *e.fallback, e.range.min, e.range.max));
  if (auto gamma = query_optional_double(q, g.name, g.range.min, g.range.max)) {
    if (*gamma <= 0.0) throw invalid_field(g.name, "must be > 0 (leave it out for the sRGB curve)");
    tone.gamma = float(*gamma);
  }
  return tone;
}

PreviewParams parse_preview_params(const Query& q, ImageFormat fallback, ToneCurve curve) {
  PreviewParams p;
  p.format = query_enum(q, "format", fallback);
  p.tone = parse_tone_map(q, curve);
  return p;
}

}  // namespace lp::api

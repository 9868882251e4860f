#include "api/preview_params.hpp"

#include "api/api_error.hpp"

namespace lp::api {

ToneMap parse_tone_map(const Query& q) {
  ToneMap tone;
  tone.exposure = float(query_double(q, "exposure", 0.0, -64.0, 64.0));
  if (auto g = query_optional_double(q, "gamma", 0.0, 10.0)) {
    if (*g <= 0.0) throw invalid_field("gamma", "must be > 0 (leave it out for the sRGB curve)");
    tone.gamma = float(*g);
  }
  return tone;
}

PreviewParams parse_preview_params(const Query& q, ImageFormat fallback) {
  PreviewParams p;
  p.format = *parse_format(query_enum(q, "format", format_name(fallback), {"png", "exr", "pfm", "hdr"}));
  p.tone = parse_tone_map(q);
  return p;
}

}  // namespace lp::api

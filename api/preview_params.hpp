#pragma once
// The query parameters every image endpoint shares: format, exposure (stops), gamma, tone_mapping.
#include "api/parameters.hpp"
#include "api/params.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

struct PreviewParams {
  ImageFormat format = ImageFormat::Png;
  ToneMap tone;
};

// `format` (png|exr|pfm|hdr, default png), `exposure` in [-64, 64], `gamma` in (0, 10] or empty = sRGB,
// `tone_mapping` (a ToneCurve name, default `curve`).
PreviewParams parse_preview_params(const Query& q, ImageFormat fallback = ImageFormat::Png,
                                   ToneCurve curve = kToneMapping.fallback);
// Only exposure, gamma and tone_mapping (for endpoints that always answer PNG).
ToneMap parse_tone_map(const Query& q, ToneCurve curve = kToneMapping.fallback);

}  // namespace lp::api

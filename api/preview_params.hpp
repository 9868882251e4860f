#pragma once
// The query parameters every image endpoint shares: format, exposure (stops), gamma.
#include "api/params.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

struct PreviewParams {
  ImageFormat format = ImageFormat::Png;
  ToneMap tone;
};

// `format` (png|exr|pfm|hdr, default png), `exposure` in [-64, 64], `gamma` in (0, 10] or empty = sRGB.
PreviewParams parse_preview_params(const Query& q, ImageFormat fallback = ImageFormat::Png);
// Only exposure and gamma (for endpoints that always answer PNG).
ToneMap parse_tone_map(const Query& q);

}  // namespace lp::api

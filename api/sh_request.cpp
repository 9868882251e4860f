#include "api/sh_request.hpp"

#include "api/preview_params.hpp"

namespace lp::api {
namespace {

ShRequest parse_common(const Query& q) {
  ShRequest r;
  r.bands = int(query_int(q, "bands", kDefaultShBands, limits::kShBands.min, limits::kShBands.max));
  r.window = query_enum(q, "window", ShWindow::None);
  return r;
}

}  // namespace

ShRequest parse_sh_query(const Query& q) {
  ShRequest r = parse_common(q);
  r.irradiance = query_bool(q, "irradiance", true);
  return r;
}

ShImageRequest parse_sh_image_query(const Query& q) {
  ShImageRequest r;
  r.sh = parse_common(q);
  r.quantity = query_enum(q, "quantity", ShQuantity::Radiance);
  if (query_string(q, "width")) r.width = int(query_int(q, "width", 0, kShImageWidth.min, kShImageWidth.max));
  r.tone = parse_tone_map(q);
  return r;
}

ShCoefficients sh_radiance(const ShCoefficients& full, const ShRequest& request) {
  return scaled_by_band(full.truncated(request.bands), sh_window_factors(request.window, request.bands));
}

}  // namespace lp::api

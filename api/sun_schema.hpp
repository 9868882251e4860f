#pragma once
// JSON shape of a sun extraction (POST /api/v1/envmaps/{id}/sun, `lightprobe sun`).
#include <optional>
#include <string>

#include "api/params.hpp"
#include "engine/sun/sun_extraction.hpp"

namespace lp::api {

// {"found", "reason" (when not found), the sun's "direction", "theta", "phi", "pixel", "angular_radius",
//  "solid_angle", "color", "irradiance", "share", "removed_radius", "removed_pixels", "fill" (when found),
//  "power": {"map", "residual", "sun"}, "residual" (its id or file, null without a sun), "parameters",
//  "elapsed_ms", "cached"}. Angles in radians.
Json sun_json(const SunExtraction& extraction, const std::optional<std::string>& residual, bool cached);

}  // namespace lp::api

#pragma once
// POST /envmaps/{id}/sun body, and the same parameters in a render's lighting.sun_parameters.
#include <string>

#include "api/params.hpp"
#include "engine/sun/sun_params.hpp"

namespace lp::api {

// {"threshold":..., "max_radius_deg":..., "min_share":..., "min_contrast":...}, every field optional
// (engine/sun/sun_params.hpp declares each: name, default, range). An empty body means all defaults.
SunParams parse_sun_request(const std::string& body);
// The same fields from an object; errors name them under `prefix` ("lighting.sun_parameters.min_share").
SunParams parse_sun_params(const Json& object, const std::string& prefix);
// {"threshold": ..., ...}: every field.
Json sun_params_json(const SunParams& params);

// The id under which the residual of map `id` is registered: "<id>-sun".
std::string sun_residual_id(const std::string& id);

}  // namespace lp::api

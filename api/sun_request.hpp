#pragma once
// POST /envmaps/{id}/sun body.
#include <string>

#include "engine/sun/sun_params.hpp"

namespace lp::api {

// {"threshold":0.05,"max_radius_deg":5,"min_share":0.05}, every field optional (defaults shown), each a
// number in its range (engine/core/limits.hpp). An empty body means all defaults.
SunParams parse_sun_request(const std::string& body);

// The id under which the residual of map `id` is registered: "<id>-sun".
std::string sun_residual_id(const std::string& id);

}  // namespace lp::api

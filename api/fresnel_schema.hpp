#pragma once
// JSON and CSV shapes of the Fresnel tables (GET /api/v1/fresnel).
#include <optional>
#include <string>

#include "api/params.hpp"
#include "engine/fresnel/fresnel_table.hpp"

namespace lp::api {

Json fresnel_json(const DielectricTable& t);
// `metal`: the preset the indices came from (adds its wavelengths), if any.
Json fresnel_json(const ConductorTable& t, const std::optional<std::string>& metal);

// One row per angle after a header row: angle_deg,rs,rp,unpolarized,schlick
std::string fresnel_csv(const DielectricTable& t);
// angle_deg,r,g,b,rs_r,rs_g,rs_b,rp_r,rp_g,rp_b (r, g, b: unpolarised per channel)
std::string fresnel_csv(const ConductorTable& t);

}  // namespace lp::api

#include "api/sun_request.hpp"

#include "api/params.hpp"
#include "engine/core/limits.hpp"

namespace lp::api {

SunParams parse_sun_request(const std::string& body) {
  const Json j = parse_json_object_or_empty(body);
  reject_unknown_fields(j, {"threshold", "max_radius_deg", "min_share"});
  using namespace limits;
  SunParams p;
  p.threshold = json_double(j, "threshold", p.threshold, kSunThreshold.min, kSunThreshold.max);
  p.max_radius_deg =
      json_double(j, "max_radius_deg", p.max_radius_deg, kSunMaxRadiusDeg.min, kSunMaxRadiusDeg.max);
  p.min_share = json_double(j, "min_share", p.min_share, kSunMinShare.min, kSunMinShare.max);
  return p;
}

std::string sun_residual_id(const std::string& id) {
  return id + "-sun";
}

}  // namespace lp::api

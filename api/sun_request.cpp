#include "api/sun_request.hpp"

namespace lp::api {

SunParams parse_sun_params(const Json& j, const std::string& prefix) {
  std::vector<std::string> names;
  for (const SunField& f : kSunFields) names.push_back(f.name);
  reject_unknown_fields(j, names, prefix);
  SunParams p;
  for (const SunField& f : kSunFields)
    p.*f.member = json_double(j, f.name, p.*f.member, f.range.min, f.range.max, prefix);
  return p;
}

SunParams parse_sun_request(const std::string& body) {
  return parse_sun_params(parse_json_object_or_empty(body), "");
}

Json sun_params_json(const SunParams& params) {
  Json out = Json::object();
  for (const SunField& f : kSunFields) out[f.name] = params.*f.member;
  return out;
}

std::string sun_residual_id(const std::string& id) {
  return id + "-sun";
}

}  // namespace lp::api

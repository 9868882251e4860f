#include "api/envmap_load_request.hpp"

#include "api/params.hpp"

namespace lp::api {

EnvMapLoadRequest parse_envmap_load_request(const std::string& body) {
  const Json j = parse_json_object(body);
  reject_unknown_fields(j, {"name", "path"});
  return {json_string(j, "name", std::nullopt), json_string(j, "path", std::nullopt)};
}

}  // namespace lp::api

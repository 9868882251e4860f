#include "api/openapi_error_codes.hpp"

#include <yaml-cpp/yaml.h>

#include "api/openapi.hpp"

namespace lp::api {

std::vector<std::string> documented_error_codes() {
  const YAML::Node doc = YAML::Load(std::string(openapi_document()));
  return doc["components"]["schemas"]["ErrorCode"]["enum"].as<std::vector<std::string>>();
}

}  // namespace lp::api

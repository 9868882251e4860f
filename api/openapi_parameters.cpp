#include "api/openapi_parameters.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "api/openapi.hpp"

namespace lp::api {
namespace {

const YAML::Node& document() {
  static const YAML::Node doc = YAML::Load(std::string(openapi_document()));
  return doc;
}

// A parameter object, or the one its "#/components/parameters/NAME" reference names.
YAML::Node resolve(const YAML::Node& parameter) {
  if (!parameter["$ref"]) return parameter;
  const std::string ref = parameter["$ref"].as<std::string>();
  const std::string prefix = "#/components/parameters/";
  if (ref.rfind(prefix, 0) != 0) throw std::logic_error("openapi.yaml: unsupported parameter $ref " + ref);
  const YAML::Node target = document()["components"]["parameters"][ref.substr(prefix.size())];
  if (!target) throw std::logic_error("openapi.yaml: dangling $ref " + ref);
  return target;
}

void add_query_names(const YAML::Node& parameters, std::vector<std::string>& names) {
  if (!parameters) return;
  for (const auto& p : parameters) {
    const YAML::Node parameter = resolve(p);
    if (parameter["in"].as<std::string>() != "query") continue;
    const std::string name = parameter["name"].as<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
}

}  // namespace

std::vector<std::string> documented_query_parameters(const std::string& method, const std::string& path) {
  std::string key = method;
  std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const YAML::Node item = document()["paths"][path];
  if (!item || !item[key])
    throw std::logic_error("openapi.yaml documents no operation " + method + " " + path);
  std::vector<std::string> names;
  add_query_names(item["parameters"], names);
  add_query_names(item[key]["parameters"], names);
  return names;
}

}  // namespace lp::api

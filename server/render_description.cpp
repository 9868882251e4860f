#include "server/render_description.hpp"

#include <stdexcept>

namespace lp::server {

std::string description_json(const RenderDescription& d) {
  return nlohmann::json{{"request", d.request}, {"envmap_hash", d.envmap_hash}, {"source_url", d.source_url}}
      .dump();
}

RenderDescription parse_description(const std::string& text) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("request") || !j["request"].is_object() ||
      !j.value("envmap_hash", nlohmann::json()).is_string() ||
      !j.value("source_url", nlohmann::json()).is_string())
    throw std::invalid_argument("not a render description");
  return {j["request"], j["envmap_hash"].get<std::string>(), j["source_url"].get<std::string>()};
}

}  // namespace lp::server

#include "server/scale_out/render_description.hpp"

#include <algorithm>
#include <stdexcept>

#include "server/scale_out/bundle_hash.hpp"

namespace lp::server {
namespace {

using nlohmann::json;

bool is_string(const json& j, const char* key) {
  return j.value(key, json()).is_string();
}

[[noreturn]] void not_a_description() {
  throw std::invalid_argument("not a render description");
}

std::vector<MeshReference> parse_meshes(const json& j) {
  std::vector<MeshReference> out;
  if (!j.contains("meshes")) return out;
  if (!j["meshes"].is_array()) not_a_description();
  for (const auto& m : j["meshes"]) {
    if (!m.is_object() || !m.value("object", json()).is_number_unsigned() || !is_string(m, "bundle") ||
        !is_string(m, "model") || !is_bundle_hash(m["bundle"].get<std::string>()))
      not_a_description();
    out.push_back({m["object"].get<size_t>(), m["bundle"].get<std::string>(), m["model"].get<std::string>()});
  }
  return out;
}

}  // namespace

const MeshReference* RenderDescription::mesh(size_t object) const {
  const auto it = std::find_if(meshes.begin(), meshes.end(),
                               [object](const MeshReference& m) { return m.object == object; });
  return it == meshes.end() ? nullptr : &*it;
}

std::string description_json(const RenderDescription& d) {
  json meshes = json::array();
  for (const auto& m : d.meshes)
    meshes.push_back({{"object", m.object}, {"bundle", m.bundle}, {"model", m.model}});
  return json{{"request", d.request},
              {"envmap_hash", d.envmap_hash},
              {"source_url", d.source_url},
              {"meshes", std::move(meshes)}}
      .dump();
}

RenderDescription parse_description(const std::string& text) {
  const auto j = json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("request") || !j["request"].is_object() || !is_string(j, "envmap_hash") ||
      !is_string(j, "source_url"))
    not_a_description();
  return {j["request"], j["envmap_hash"].get<std::string>(), j["source_url"].get<std::string>(),
          parse_meshes(j)};
}

}  // namespace lp::server

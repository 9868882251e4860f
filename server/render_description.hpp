#pragma once
// What a worker needs to render items of a render it did not receive: the request as the client sent it
// (scene, lighting, settings and seed), the content hash of its map (envmap_fingerprint.hpp) and where
// to fetch the map by that hash. Stored as JSON under the render's key in Redis. Meshes are found by
// their paths in the worker's own --data-dir.
#include <nlohmann/json.hpp>
#include <string>

namespace lp::server {

struct RenderDescription {
  nlohmann::json request;  // the POST /api/v1/renders body
  std::string envmap_hash;
  std::string source_url;  // the coordinator: http://HOST:PORT
};

std::string description_json(const RenderDescription& d);
// Throws std::invalid_argument for text that is not a description.
RenderDescription parse_description(const std::string& text);

}  // namespace lp::server

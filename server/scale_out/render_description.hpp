#pragma once
// What a worker needs to render items of a render it did not receive: the request as the client sent it
// (scene, lighting, settings and seed), the content hash of its map (maps/envmap_content_hash.hpp), the mesh
// bundle of each mesh object read from files (mesh_bundles.hpp) and where to fetch the map and the
// bundles by their hashes. Stored as JSON under the render's key in Redis.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lp::server {

// A mesh object's files: scene.objects[object] is the model file `model` of the bundle `bundle`.
struct MeshReference {
  size_t object = 0;
  std::string bundle;  // its hash (bundle_hash.hpp)
  std::string model;   // '/'-separated, inside the bundle
};

struct RenderDescription {
  nlohmann::json request;  // the POST /api/v1/renders body
  std::string envmap_hash;
  std::string source_url;  // the coordinator: http://HOST:PORT
  std::vector<MeshReference> meshes;

  // The reference of scene.objects[object]; nullptr when there is none.
  const MeshReference* mesh(size_t object) const;
};

std::string description_json(const RenderDescription& d);
// Throws std::invalid_argument for text that is not a description (a bundle named by anything but a
// bundle hash included).
RenderDescription parse_description(const std::string& text);

}  // namespace lp::server

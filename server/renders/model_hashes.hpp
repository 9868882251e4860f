#pragma once
// The content hashes of the models a render's mesh objects were read from (storage/content_hash.hpp): over
// the model file and every file it was read from (Model::files), by their paths inside the model file's
// folder. A render keeps them with the image of its finished passes, and continues that image only on
// models of the same hashes.
#include <cstddef>
#include <map>
#include <string>

#include "engine/model/model.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::server {

// Empty when a file cannot be read or changed on disk after the model was read: no hash then names the
// model in memory.
std::string model_content_hash(const Model& model);

// By the index of the mesh object in `scene`; objects whose model was not read from files have none.
using ModelHashes = std::map<size_t, std::string>;
ModelHashes model_content_hashes(const render::SceneDesc& scene);

}  // namespace lp::server

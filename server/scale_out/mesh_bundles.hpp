#pragma once
// The coordinator's side of meshes for renders split over machines: a mesh object whose model was read
// from files (not a preset's, built in memory) goes to workers as a bundle, the model file and every file
// it was read from (Model::files: material libraries, textures, buffers, images), by their paths inside
// the model file's folder, named by its content hash (bundle_hash.hpp). A render publishes the bundles of
// its scene; GET /api/v1/content/{hash} serves a published bundle as a tar (bundle_archive.hpp). The
// last few bundles stay published; a hash is computed again only when a file's size or time changed.
// Thread-safe.
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "engine/model/model.hpp"
#include "engine/render/scene_desc.hpp"
#include "server/scale_out/recent_list.hpp"
#include "server/scale_out/render_description.hpp"

namespace lp::server {

struct MeshBundle {
  std::string hash;
  std::filesystem::path folder;    // the model file's folder
  std::vector<std::string> files;  // inside it, '/'-separated, the model file first
  std::string model;               // the model file, inside it
};

// The bundle of a model read from files. Throws std::runtime_error when a file cannot be read.
MeshBundle mesh_bundle(const Model& model);

class MeshBundles {
 public:
  // The references of the scene's mesh objects read from files, their bundles published.
  std::vector<MeshReference> publish(const render::SceneDesc& scene);
  // A published bundle.
  std::optional<MeshBundle> find(const std::string& hash) const;

 private:
  MeshBundle bundle_of(const Model& model);

  static constexpr size_t kKept = 64;
  mutable std::mutex mutex_;
  RecentList<std::vector<FileStamp>, MeshBundle> kept_{kKept};  // by the files when they were hashed
};

}  // namespace lp::server

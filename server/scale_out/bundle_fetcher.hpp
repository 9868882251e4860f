#pragma once
// The mesh bundles a worker renders with (mesh_bundles.hpp), by content hash: kept in its state
// directory under fetched/HASH/, else fetched from the coordinator (GET /api/v1/content/{hash}, a tar of
// at most --max-asset-mb unpacked in at most --max-asset-files members), unpacked with the limits of
// an uploaded asset, checked against the hash and kept for the next items and renders (the last few, by
// last use; the folder is emptied at start). The download's bytes are reserved in the memory budget.
#include <filesystem>
#include <mutex>
#include <string>

#include "server/app.hpp"
#include "server/scale_out/recent_list.hpp"
#include "server/scale_out/render_description.hpp"

namespace lp::server {

class BundleFetcher {
 public:
  explicit BundleFetcher(App& app);

  // The model file of `mesh`, inside its bundle's folder. Throws std::runtime_error when the
  // coordinator does not have the bundle, sends one over the limits or one whose files do not match its
  // hash; api::ApiError (naming `field`) for a model path outside the bundle.
  std::filesystem::path model_file(const MeshReference& mesh, const std::string& source_url,
                                   const std::string& field);

 private:
  std::filesystem::path folder(const std::string& hash) const { return root_ / hash; }
  void fetch(const std::string& hash, const std::string& source_url);

  static constexpr size_t kKept = 8;
  App& app_;
  const std::filesystem::path root_;  // empty without a state directory
  std::mutex mutex_;
  RecentList<std::string> kept_{kKept};  // hashes
};

}  // namespace lp::server

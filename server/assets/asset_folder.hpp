#pragma once
// The files of one model asset in a folder of its own: an uploaded .glb or self-contained .gltf kept as
// is, or a zip or tar archive unpacked (archive_unpacker.hpp). The folder is staged under a temporary name
// beside its place and renamed into place whole, so a crash leaves it complete or absent.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "server/assets/archive_unpacker.hpp"

namespace lp::server {

struct AssetFiles {
  std::string model;  // the model file inside the folder, '/'-separated
  int64_t bytes = 0;  // all files together
  int64_t files = 0;
};

// The names an uploaded .glb and .gltf are kept under in their folder.
inline constexpr std::string_view kGlbFileName = "model.glb";
inline constexpr std::string_view kGltfFileName = "model.gltf";

// Whether a file name ends in .glb, .gltf or .obj (any case).
bool is_model_file_name(const std::string& path);

// Whether the bytes start as a binary glTF file does (the magic "glTF").
bool is_glb(std::span<const uint8_t> bytes);
// Whether the bytes start as a glTF JSON document does: '{' after any white space.
bool is_gltf_json(std::span<const uint8_t> bytes);

// The one model file among unpacked files: at the top level, or directly inside the top folder when all
// files lie in one. Throws api::ApiError 400 saying what was found instead.
std::string find_model_file(const std::vector<UnpackedFile>& files);

// An asset's folder written under a temporary name; removed unless committed.
class StagedAsset {
 public:
  // Writes `upload` (a .glb or .gltf, or an archive to unpack under `limits`) for the folder `target`. Throws
  // api::ApiError for an upload refused, StorageError or std::filesystem::filesystem_error for an I/O
  // failure.
  StagedAsset(std::span<const uint8_t> upload, std::filesystem::path target, const ArchiveLimits& limits);
  ~StagedAsset();
  StagedAsset(const StagedAsset&) = delete;
  StagedAsset& operator=(const StagedAsset&) = delete;

  const AssetFiles& files() const { return files_; }
  // Renames the folder to `target` (which must not exist) and flushes its parent.
  void commit();

 private:
  std::filesystem::path target_, staging_;
  AssetFiles files_;
  bool committed_ = false;
};

}  // namespace lp::server

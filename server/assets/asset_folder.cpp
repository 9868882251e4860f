#include "server/assets/asset_folder.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <stdexcept>

#include "api/api_error.hpp"
#include "engine/model/model_loader.hpp"
#include "server/storage/atomic_file.hpp"
#include "server/storage/storage_error.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

constexpr size_t kListedFiles = 4;  // model files named in a refusal

std::string first_component(const std::string& path) {
  return path.substr(0, path.find('/'));
}

// "a", "b", "c" and 2 more.
std::string listing(const std::vector<std::string>& paths) {
  std::string out;
  for (size_t i = 0; i < paths.size() && i < kListedFiles; ++i)
    out += (i ? ", '" : "'") + api::excerpt(paths[i]) + "'";
  if (paths.size() > kListedFiles) out += fmt::format(" and {} more", paths.size() - kListedFiles);
  return out;
}

// "folder/" when every file lies inside one top folder, else "".
std::string common_top_folder(const std::vector<UnpackedFile>& files) {
  if (files.empty() || files.front().path.find('/') == std::string::npos) return "";
  const std::string top = first_component(files.front().path);
  for (const auto& f : files)
    if (f.path.find('/') == std::string::npos || first_component(f.path) != top) return "";
  return top + "/";
}

[[noreturn]] void refuse(const std::string& what) {
  throw api::ApiError(api::ErrorCode::InvalidArgument,
                      what +
                          "; an asset holds exactly one model file (.glb, .gltf or .obj) at the top level "
                          "of its archive or inside a single top folder");
}

AssetFiles write_model(std::span<const uint8_t> upload, const fs::path& folder, std::string_view name) {
  NewFile file(folder / name);
  file.write(upload);
  file.finish();
  return {std::string(name), int64_t(upload.size()), 1};
}

AssetFiles write_archive(std::span<const uint8_t> upload, const fs::path& folder,
                         const ArchiveLimits& limits) {
  const auto files = unpack_archive(upload, folder, limits);
  AssetFiles out{find_model_file(files), 0, int64_t(files.size())};
  for (const auto& f : files) out.bytes += f.bytes;
  return out;
}

// Every folder below `folder` (and itself), flushed so that the files' names are on disk too.
void sync_folders(const fs::path& folder) {
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_directory()) sync_directory(entry.path());
  sync_directory(folder);
}

}  // namespace

bool is_model_file_name(const std::string& path) {
  return !model_format(path).empty();
}

bool is_glb(std::span<const uint8_t> bytes) {
  constexpr std::array<uint8_t, 4> kMagic = {'g', 'l', 'T', 'F'};
  return bytes.size() >= kMagic.size() && std::equal(kMagic.begin(), kMagic.end(), bytes.begin());
}

bool is_gltf_json(std::span<const uint8_t> bytes) {
  const auto first = std::find_if(bytes.begin(), bytes.end(), [](uint8_t c) { return !std::isspace(c); });
  return first != bytes.end() && *first == '{';
}

std::string find_model_file(const std::vector<UnpackedFile>& files) {
  const std::string root = common_top_folder(files);
  std::vector<std::string> models, deeper;
  for (const auto& f : files) {
    if (!is_model_file_name(f.path)) continue;
    const bool at_root = f.path.find('/', root.size()) == std::string::npos;
    (at_root ? models : deeper).push_back(f.path);
  }
  if (models.size() == 1) return models.front();
  if (models.size() > 1)
    refuse(fmt::format("the archive holds {} model files: {}", models.size(), listing(models)));
  if (!deeper.empty())
    refuse(fmt::format("the archive's model files lie in nested folders: {}", listing(deeper)));
  refuse(fmt::format("the archive holds no model file among its {} files", files.size()));
}

StagedAsset::StagedAsset(std::span<const uint8_t> upload, fs::path target, const ArchiveLimits& limits)
    : target_(std::move(target)), staging_(temporary_path_for(target_)) {
  if (!fs::create_directory(staging_)) throw StorageError("create a folder", staging_, EEXIST);
  try {
    if (is_glb(upload))
      files_ = write_model(upload, staging_, kGlbFileName);
    else if (is_gltf_json(upload))
      files_ = write_model(upload, staging_, kGltfFileName);
    else
      files_ = write_archive(upload, staging_, limits);
    sync_folders(staging_);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
    throw;
  }
}

StagedAsset::~StagedAsset() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (ec) spdlog::warn("state: cannot remove {}: {}", staging_.string(), ec.message());
}

void StagedAsset::commit() {
  if (::rename(staging_.c_str(), target_.c_str()) != 0) {
    if (errno == EEXIST || errno == ENOTEMPTY)
      throw api::ApiError(api::ErrorCode::Conflict,
                          "the state directory holds files of an earlier asset named '" +
                              target_.filename().string() +
                              "' that could not be restored (see the server's log)");
    throw StorageError("rename a folder", staging_, errno);
  }
  committed_ = true;
  sync_directory(target_.parent_path());
}

}  // namespace lp::server

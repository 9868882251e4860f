#include "server/scale_out/bundle_fetcher.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <span>
#include <stdexcept>
#include <system_error>

#include "api/api_error.hpp"
#include "server/assets/archive_unpacker.hpp"
#include "server/scale_out/bundle_archive.hpp"
#include "server/scale_out/bundle_hash.hpp"
#include "server/scale_out/content_download.hpp"
#include "server/storage/data_dir.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

fs::path fetched_root(const App& app) {
  return app.state ? app.state->dir() / "fetched" : fs::path();
}

void remove_folder(const fs::path& folder) {
  std::error_code ec;
  fs::remove_all(folder, ec);
  if (ec) spdlog::warn("cannot remove {}: {}", folder.string(), ec.message());
}

}  // namespace

BundleFetcher::BundleFetcher(App& app) : app_(app), root_(fetched_root(app)) {
  if (root_.empty()) return;
  remove_folder(root_);  // what an earlier run fetched is not counted among the kept bundles
  std::error_code ec;
  fs::create_directories(root_, ec);
  if (ec) spdlog::warn("cannot create {}: {}", root_.string(), ec.message());
}

fs::path BundleFetcher::model_file(const MeshReference& mesh, const std::string& source_url,
                                   const std::string& field) {
  if (root_.empty()) throw std::runtime_error("a worker needs a state directory to keep mesh bundles in");
  if (!is_bundle_hash(mesh.bundle))
    throw std::runtime_error("'" + api::excerpt(mesh.bundle) + "' is no bundle hash");
  std::lock_guard lock(mutex_);
  if (!kept_.use(mesh.bundle)) {
    fetch(mesh.bundle, source_url);
    for (const auto& [dropped, _] : kept_.add(mesh.bundle, {})) remove_folder(folder(dropped));
  }
  return resolve_inside(folder(mesh.bundle), mesh.model, field, "the mesh bundle " + mesh.bundle);
}

void BundleFetcher::fetch(const std::string& hash, const std::string& source_url) {
  const ArchiveLimits limits = app_.options.assets.archive();
  Download download =
      download_content(app_, source_url, hash, bundle_tar_bytes(limits.max_bytes, limits.max_members),
                       "the mesh bundle " + hash);
  const fs::path staging = root_ / (hash + ".partial");
  remove_folder(staging);
  fs::create_directories(staging);
  std::vector<std::string> files;
  try {
    for (auto& file : unpack_archive(
             std::span(reinterpret_cast<const uint8_t*>(download.bytes.data()), download.bytes.size()),
             staging, limits))
      files.push_back(std::move(file.path));
  } catch (const api::ApiError& e) {
    remove_folder(staging);
    throw std::runtime_error(
        fmt::format("the mesh bundle {} from {} cannot be unpacked: {}", hash, source_url, e.what()));
  }
  const int64_t bytes = int64_t(download.bytes.size());
  download = {};
  if (bundle_hash(staging, files) != hash) {
    remove_folder(staging);
    throw std::runtime_error(
        fmt::format("the mesh bundle fetched from {} does not match its hash {}", source_url, hash));
  }
  remove_folder(folder(hash));
  fs::rename(staging, folder(hash));
  spdlog::info("fetched mesh bundle {} from {} ({} files, {} bytes)", hash, source_url, files.size(), bytes);
}

}  // namespace lp::server

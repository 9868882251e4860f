#include "server/assets/stored_assets.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <optional>

#include "api/api_error.hpp"
#include "api/model_info_schema.hpp"
#include "api/render_request.hpp"
#include "engine/model/model_info.hpp"
#include "server/assets/asset_folder.hpp"
#include "server/storage/data_dir.hpp"
#include "server/storage/resource_name.hpp"
#include "server/storage/storage_error.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::system_clock;

constexpr int kRecordVersion = 1;

struct MissingFolder {};  // a record whose files are gone

fs::path record_path(const StateStore& store, const std::string& name) {
  return store.assets_dir() / (name + ".json");
}

StateStore& state_of(App& app) {
  if (!app.state) throw api::ApiError(api::ErrorCode::Internal, "the server keeps no state directory");
  return *app.state;
}

nlohmann::json record_of(const api::AssetInfo& info) {
  return {{"version", kRecordVersion},
          {"name", info.name},
          {"model", info.model},
          {"bytes", info.bytes},
          {"files", info.files},
          {"created_ms",
           std::chrono::duration_cast<std::chrono::milliseconds>(info.created.time_since_epoch()).count()},
          {"description", info.description}};
}

void check_upload_size(const App& app, size_t bytes) {
  if (bytes == 0)
    throw api::ApiError(api::ErrorCode::EmptyBody,
                        "the request body is empty: send a .glb file, or a zip or tar archive of a model");
  const int64_t limit = app.options.assets.max_asset_mb << 20;
  if (int64_t(bytes) > limit)
    throw api::ApiError(api::ErrorCode::TooLarge,
                        fmt::format("the upload is {} bytes, more than --{} allows ({} MiB)", bytes,
                                    kMaxAssetMb.flag, app.options.assets.max_asset_mb));
}

api::AssetInfo restored_info(const StateStore& store, const nlohmann::json& record) {
  if (record.at("version").get<int>() != kRecordVersion)
    throw std::invalid_argument("unknown record version");
  api::AssetInfo info{record.at("name").get<std::string>(),
                      record.at("model").get<std::string>(),
                      record.at("bytes").get<int64_t>(),
                      record.at("files").get<int64_t>(),
                      Clock::time_point(std::chrono::milliseconds(record.at("created_ms").get<int64_t>())),
                      record.value("description", api::Json())};
  if (!valid_resource_name(info.name)) throw std::invalid_argument("not an asset name: '" + info.name + "'");
  if (!is_model_file_name(info.model)) throw std::invalid_argument("not a model file: '" + info.model + "'");
  const fs::path folder = asset_folder(store, info.name);
  if (!fs::is_directory(fs::symlink_status(folder))) throw MissingFolder();
  resolve_inside(folder, info.model, "model", "the asset's folder");
  return info;
}

// State directories written before records and files lived apart kept an asset's folder beside its
// record, in assets/: moves such folders to asset-files/.
void move_folders_beside_records(const StateStore& store) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(store.assets_dir(), ec)) {
    const fs::path target = store.asset_files_dir() / entry.path().filename();
    if (!entry.is_directory() || fs::exists(target)) continue;
    spdlog::info("state: moving {} to {}", fs::relative(entry.path(), store.dir()).string(),
                 fs::relative(target, store.dir()).string());
    fs::rename(entry.path(), target, ec);
  }
}

// What no record names: folders an upload a crash cut short after its rename left, and anything in
// assets/ but records.
void remove_unrecorded_files(const StateStore& store) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(store.asset_files_dir(), ec))
    if (!fs::exists(record_path(store, entry.path().filename().string())))
      store.remove_leftover(entry.path());
  for (const auto& entry : fs::directory_iterator(store.assets_dir(), ec))
    if (entry.path().extension() != ".json" || !entry.is_regular_file()) store.remove_leftover(entry.path());
}

// Loads the model file as a render loads it, into the model cache where the first render finds it,
// and describes it. Throws ApiError 422 invalid_model naming what is wrong, 413 too_large past a model
// limit, and MemoryBudgetError when the model does not fit in memory.
api::Json describe_stored_model(App& app, const fs::path& file) {
  std::shared_ptr<const Model> model;
  try {
    model = app.models.get(file, api::model_limits(app.options.limits));
  } catch (const MemoryBudgetError&) {
    throw;
  } catch (const Error& e) {
    throw api::invalid_model(e);
  }
  return api::model_info_json(describe_model(*model));
}

void write_record(StateStore& store, const api::AssetInfo& info) {
  std::lock_guard lock(store.assets_mutex());
  store.write_record(record_path(store, info.name), record_of(info));
}

}  // namespace

fs::path asset_folder(const StateStore& store, const std::string& name) {
  return store.asset_files_dir() / name;
}

std::shared_ptr<const api::AssetInfo> store_asset(App& app, const std::string& name,
                                                  std::span<const uint8_t> upload) {
  StateStore& store = state_of(app);
  const auto pending = app.assets.hold(name);
  check_upload_size(app, upload.size());
  // The body is held while it unpacks; the files go to disk through small buffers. (libarchive's index
  // of a zip's central directory, a few times its size, is not counted: --max-asset-mb bounds it.)
  const auto memory =
      app.memory.reserve(int64_t(upload.size()), MemoryUse::Transient, "unpacking the asset '" + name + "'");
  const ArchiveLimits limits = app.options.assets.archive();
  const fs::path folder = asset_folder(store, name);
  const std::string what = "the asset '" + name + "'";
  std::optional<StagedAsset> staged;
  try {
    staged.emplace(upload, folder, limits);
    std::lock_guard lock(store.assets_mutex());
    staged->commit();
  } catch (const StorageError& e) {
    throw storage_refusal(e, what);
  } catch (const fs::filesystem_error& e) {
    throw storage_refusal(e, what);
  }
  api::AssetInfo info{name, staged->files().model, staged->files().bytes, staged->files().files, Clock::now(),
                      {}};
  // The model is loaded from its place, as a render names it; until the record is written the folder is
  // a leftover that a restart removes, and the held name keeps renders and deletes away from it.
  try {
    info.description =
        describe_stored_model(app, resolve_inside(folder, info.model, "model", "the asset's folder"));
    try {
      write_record(store, info);
    } catch (const StorageError& e) {
      throw storage_refusal(e, what);
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
    throw;
  }
  spdlog::info("stored asset '{}' ({}, {} files, {} bytes)", name, info.model, info.files, info.bytes);
  return pending->add(info);
}

bool remove_asset(App& app, const std::string& name) {
  StateStore& store = state_of(app);
  std::lock_guard lock(store.assets_mutex());
  if (!app.assets.remove(name)) return false;
  store.remove(record_path(store, name));  // the record first: without it the folder is a leftover
  std::error_code ec;
  fs::remove_all(asset_folder(store, name), ec);
  if (ec) spdlog::warn("state: cannot remove the files of asset '{}': {}", name, ec.message());
  return true;
}

void restore_assets(App& app) {
  const StateStore& store = *app.state;
  move_folders_beside_records(store);
  int restored = 0;
  for (const auto& [path, record] : store.read_records(store.assets_dir())) {
    try {
      if (path.filename() != record.value("name", "") + ".json")
        throw std::invalid_argument("the file name is not the asset's");
      const api::AssetInfo info = restored_info(store, record);
      app.assets.hold(info.name)->add(info);
      ++restored;
    } catch (const MissingFolder&) {
      spdlog::warn("state: dropping {}: the asset's files are missing",
                   fs::relative(path, store.dir()).string());
      store.remove(path);
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping asset {}: {}", path.string(), e.what());
    }
  }
  remove_unrecorded_files(store);
  spdlog::info("state: {} asset(s) restored", restored);
}

}  // namespace lp::server

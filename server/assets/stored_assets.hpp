#pragma once
// Model assets in the state directory: asset-files/NAME/ holds an asset's files (a .glb as uploaded, or an
// archive unpacked), assets/NAME.json its record naming the model file; apart, so that no asset's files
// can take another's record name. The folder is renamed into place whole before the record is written and
// removed after it, so the record is the truth: at start every recorded asset is registered again, a
// record whose folder is missing is dropped, and a folder no record names is a leftover and removed.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "server/app.hpp"

namespace lp::server {

// Stores an upload as the asset `name`: the name is held (400, 409, 507), the upload checked against
// --max-asset-mb (413), unpacked under --max-asset-mb and --max-asset-files (archive_unpacker.hpp),
// renamed into place, its model loaded into the model cache as a render loads it and described (422
// invalid_model, 413 past a model limit, the folder removed), recorded and registered. A write that fails
// leaves nothing (507 insufficient_storage when the disk is full, else 500 write_failed). Throws
// api::ApiError, or MemoryBudgetError when the model does not fit in memory.
std::shared_ptr<const api::AssetInfo> store_asset(App& app, const std::string& name,
                                                  std::span<const uint8_t> upload);

// Unregisters an asset and deletes its record and files; false if there is no such asset.
bool remove_asset(App& app, const std::string& name);

// Moves the folders of a state directory written before asset-files/ there, registers every recorded
// asset whose files are there (a record whose folder is missing is dropped, one that cannot be read is
// skipped with a warning and kept for a later start), and removes what no record names (logged).
void restore_assets(App& app);

// The folder of asset `name`.
std::filesystem::path asset_folder(const StateStore& store, const std::string& name);

}  // namespace lp::server

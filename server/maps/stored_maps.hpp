#pragma once
// Maps across restarts: an uploaded map is kept in the state directory as uploaded, a map loaded by path
// is remembered by its path in the data directory (not copied); both are registered again at start under
// their names. Maps given with --load come back from the command line and are not kept.
#include <cstdint>
#include <span>
#include <string>

#include "server/app.hpp"

namespace lp::server {

// Keeps a map just registered: `uploaded` holds its file, or is empty for a map loaded by path (entry.source
// "path:<relative>"). Does nothing if the map was deleted meanwhile. When a write fails the map is
// unregistered and nothing of it kept: throws api::ApiError 507 insufficient_storage (disk full) or 500.
void keep_map(App& app, const std::shared_ptr<const EnvMapEntry>& entry, std::span<const uint8_t> uploaded);

// Unregisters a map and deletes what the state directory keeps of it; false if there is no such map.
bool remove_map(App& app, const std::string& id);

// Registers every kept map; one that cannot be loaded is skipped with a warning (and kept for a later start),
// a record whose uploaded file is missing is dropped, and files no record names are removed (logged).
void restore_maps(App& app);

}  // namespace lp::server

#pragma once
// Files named in requests (maps, meshes) come only from inside --data-dir (or, for meshes, an uploaded
// asset's folder: assets/mesh_paths.hpp).
#include <filesystem>
#include <string>

#include "server/options.hpp"

namespace lp::server {

// Checks at start that --data-dir, if given, is a directory the server can list and read; throws
// std::runtime_error saying what is wrong.
void check_data_dir(const Options& options);

// Resolves `relative` inside the data dir. Throws ApiError 400 naming `field` if there is no data
// dir, the path is absolute, has a ".." component, resolves (through links) outside the dir, or names
// no file: the path is a field of the request, not the resource it addresses.
std::filesystem::path resolve_in_data_dir(const Options& options, const std::string& relative,
                                          const std::string& field);

// The same checks inside any folder `root`, which messages call `where` ("the data directory").
std::filesystem::path resolve_inside(const std::filesystem::path& root, const std::string& relative,
                                     const std::string& field, const std::string& where);

}  // namespace lp::server

#pragma once
// Where a scene object's mesh path points: "assets/NAME" to the model file of the uploaded asset NAME,
// "assets/NAME/FILE" to a file inside that asset's folder, and any other path into --data-dir.
#include <filesystem>
#include <string>

#include "server/app.hpp"

namespace lp::server {

// The file a mesh path names. Throws ApiError 400 naming `field` for an unknown asset, a path that
// leaves the asset's folder or the data directory (resolve_in_data_dir), or no such file; 409 conflict
// when the asset is deleted while its path resolves.
std::filesystem::path resolve_mesh_path(const App& app, const std::string& path, const std::string& field);

}  // namespace lp::server

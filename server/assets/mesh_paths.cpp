#include "server/assets/mesh_paths.hpp"

#include "api/api_error.hpp"
#include "api/asset_schema.hpp"
#include "server/assets/stored_assets.hpp"
#include "server/storage/data_dir.hpp"

namespace lp::server {

std::filesystem::path resolve_mesh_path(const App& app, const std::string& path, const std::string& field) {
  if (!path.starts_with(api::kAssetPathPrefix)) return resolve_in_data_dir(app.options, path, field);
  const std::string rest = path.substr(api::kAssetPathPrefix.size());
  const size_t slash = rest.find('/');
  const std::string name = rest.substr(0, slash);
  const auto asset = app.assets.find(name);
  if (!asset || !app.state)
    throw api::invalid_field(field, "no asset named '" + api::excerpt(name) + "' (see GET /api/v1/assets)");
  const std::string inside = slash == std::string::npos ? asset->model : rest.substr(slash + 1);
  try {
    return resolve_inside(asset_folder(*app.state, name), inside, field, "the asset '" + name + "'");
  } catch (const api::ApiError&) {
    if (app.assets.find(name) == asset) throw;
    throw api::ApiError(api::ErrorCode::Conflict,
                        "the asset '" + api::excerpt(name) + "' was deleted while the render was accepted");
  }
}

}  // namespace lp::server

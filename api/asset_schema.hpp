#pragma once
// JSON shape of model assets (POST /api/v1/assets), and how a scene names one.
#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

#include "api/params.hpp"

namespace lp::api {

struct AssetInfo {
  std::string name;
  std::string model;  // the model file inside the asset's folder, '/'-separated
  int64_t bytes = 0;  // all its files together
  int64_t files = 0;
  std::chrono::system_clock::time_point created;
  // The model's description (model_info_schema.hpp), computed when the asset was stored; null for an
  // asset stored by a server that did not describe its models.
  Json description;
};

// A scene object's mesh path "assets/NAME" names the model file of asset NAME, and "assets/NAME/FILE"
// a file inside it; other paths lie in --data-dir.
inline constexpr std::string_view kAssetPathPrefix = "assets/";

// "glb", "gltf" or "obj": the model file's extension, lowercase.
std::string asset_format(const AssetInfo& info);

// The asset's fields, then its model's description.
Json asset_metadata(const AssetInfo& info);

}  // namespace lp::api

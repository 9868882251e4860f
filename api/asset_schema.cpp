#include "api/asset_schema.hpp"

#include <fmt/chrono.h>

#include <algorithm>
#include <filesystem>

namespace lp::api {

std::string asset_format(const AssetInfo& info) {
  std::string ext = std::filesystem::path(info.model).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

Json asset_metadata(const AssetInfo& info) {
  return {{"name", info.name},
          {"model", info.model},
          {"format", asset_format(info)},
          {"bytes", info.bytes},
          {"files", info.files},
          {"path", std::string(kAssetPathPrefix) + info.name},
          {"created",
           fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(info.created))}};
}

}  // namespace lp::api

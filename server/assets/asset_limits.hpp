#pragma once
// How many model assets the server keeps, and how large one may be, as uploaded and as unpacked. The
// flags that set them are declared here.
#include <cstdint>

#include "api/parameters.hpp"
#include "server/assets/archive_unpacker.hpp"

namespace lp::server {

inline constexpr api::IntParameter kMaxAssets{
    "max-assets", 64, {1, 100000}, "most model assets stored at once"};
inline constexpr api::IntParameter kMaxAssetMb{
    "max-asset-mb", 128,
    {1, 1 << 20},   "largest model asset in MiB, as uploaded and as unpacked",
    nullptr,        api::ErrorCode::TooLarge};
inline constexpr api::IntParameter kMaxAssetFiles{
    "max-asset-files", 1000,
    {1, 1 << 20},      "most members (files and folders) in an asset's archive",
    nullptr,           api::ErrorCode::TooLarge};

struct AssetLimits {
  int64_t max_assets = kMaxAssets.fallback;
  int64_t max_asset_mb = kMaxAssetMb.fallback;  // an upload, and its unpacked files together
  int64_t max_asset_files = kMaxAssetFiles.fallback;

  // What an asset's archive may unpack to (and a mesh bundle a worker fetches).
  ArchiveLimits archive() const { return {max_asset_mb << 20, max_asset_files}; }
};

}  // namespace lp::server

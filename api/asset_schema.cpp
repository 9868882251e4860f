#include "api/asset_schema.hpp"

#include <fmt/chrono.h>

#include "engine/model/model_loader.hpp"

namespace lp::api {

std::string asset_format(const AssetInfo& info) {
  return model_format(info.model);
}

Json asset_metadata(const AssetInfo& info) {
  Json out = {{"name", info.name},
              {"model", info.model},
              {"format", asset_format(info)},
              {"bytes", info.bytes},
              {"files", info.files},
              {"path", std::string(kAssetPathPrefix) + info.name},
              {"created",
               fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(info.created))}};
  if (info.description.is_object()) out.update(info.description);
  return out;
}

}  // namespace lp::api

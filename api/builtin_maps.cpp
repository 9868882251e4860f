#include "api/builtin_maps.hpp"

#include "engine/envmap/procedural_sky.hpp"

namespace lp::api {

std::optional<Image> builtin_map(std::string_view name) {
  if (name == kDefaultEnvmapName) return make_procedural_sky();
  return std::nullopt;
}

}  // namespace lp::api

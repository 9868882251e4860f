#pragma once
// The maps that need no file, known by name: `default`, the procedural sky the server holds when it
// starts without --load, and which the command-line tool takes wherever it reads a map.
#include <optional>
#include <string_view>

#include "engine/image/image.hpp"

namespace lp::api {

inline constexpr std::string_view kDefaultEnvmapName = "default";

// The image of the built-in map of this name, or nullopt if there is none.
std::optional<Image> builtin_map(std::string_view name);

}  // namespace lp::api

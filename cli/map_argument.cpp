#include "cli/map_argument.hpp"

#include "api/builtin_maps.hpp"
#include "cli/help.hpp"
#include "cli/image_input.hpp"
#include "engine/core/error.hpp"

namespace lp::cli {

LoadedMap load_map(const std::string& name_or_path, InvalidPixelPolicy policy,
                   const std::filesystem::path& base) {
  if (auto builtin = api::builtin_map(name_or_path))
    return {name_or_path, "procedural", "procedural",
            std::make_shared<const EnvMap>(std::move(*builtin), policy)};
  const std::filesystem::path path = base / name_or_path;
  DecodedImage decoded = read_input_image(path);
  try {
    return {path.stem().string(), enum_name(decoded.format), path.string(),
            std::make_shared<const EnvMap>(std::move(decoded.image), policy)};
  } catch (const Error& e) {
    throw Error(e.kind(), path.string() + ": " + e.what());
  }
}

InvalidPixelPolicy take_invalid_pixel_policy(Arguments& args) {
  return args.take_enum("invalid", kDefaultInvalidPixelPolicy);
}

std::string invalid_pixel_policy_help() {
  return option_line("--invalid NAME", choices(kDefaultInvalidPixelPolicy) +
                                           ": negative values become 0 and NaN or Inf pixels black\n"
                                           "(clamp), or the map is refused (reject)");
}

}  // namespace lp::cli

#pragma once
// A map named on the command line or in a scene file: a built-in name (`default`, the procedural sky) or
// an image file, OpenEXR, PFM or Radiance HDR (told by its bytes), read under the API's image limits and
// with its negative and non-finite pixels handled as the API's `invalid` parameter says.
#include <filesystem>
#include <memory>
#include <string>

#include "cli/arguments.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/invalid_pixels.hpp"

namespace lp::cli {

struct LoadedMap {
  std::string name;    // the built-in name, or the file's stem
  std::string format;  // "procedural", or the file's format: exr, pfm, hdr
  std::string source;  // "procedural", or the file's path
  std::shared_ptr<const EnvMap> map;
};

// A relative file path is taken from `base`. Throws lp::Error (NotFound, Corrupt, TooLarge, ...) naming
// the file.
LoadedMap load_map(const std::string& name_or_path, InvalidPixelPolicy policy,
                   const std::filesystem::path& base = {});

// --invalid clamp|reject, taken from the arguments, and its help line.
InvalidPixelPolicy take_invalid_pixel_policy(Arguments& args);
std::string invalid_pixel_policy_help();

}  // namespace lp::cli

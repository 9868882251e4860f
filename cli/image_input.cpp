#include "cli/image_input.hpp"

#include "engine/core/error.hpp"

namespace lp::cli {

DecodedImage read_input_image(const std::filesystem::path& path) {
  try {
    return read_image_file(path, ImageLimits{});
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::NotFound) throw;  // its message names the file
    throw Error(e.kind(), path.string() + ": " + e.what());
  }
}

}  // namespace lp::cli

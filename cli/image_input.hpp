#pragma once
// Reading an image file the tool was given: OpenEXR, PFM or Radiance HDR, told by its bytes, under the
// API's image limits (--max-pixels' default).
#include <filesystem>

#include "engine/image/image_io.hpp"

namespace lp::cli {

// Throws lp::Error (NotFound, Unsupported, Corrupt, TooLarge) with a message naming the file.
DecodedImage read_input_image(const std::filesystem::path& path);

}  // namespace lp::cli

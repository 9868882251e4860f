#include <cstdlib>

#include "engine/denoise/denoiser.hpp"

namespace lp::denoise {

// LIGHTPROBE_DENOISE_WEIGHTS when set, else the installed weights when present, else this source tree's.
std::filesystem::path default_weights_dir() {
  if (const char* env = std::getenv("LIGHTPROBE_DENOISE_WEIGHTS"); env && *env) return env;
  const std::filesystem::path installed = LIGHTPROBE_DENOISE_INSTALLED_WEIGHTS;
  std::error_code error;
  if (std::filesystem::is_directory(installed, error)) return installed;
  return LIGHTPROBE_DENOISE_SOURCE_WEIGHTS;
}

}  // namespace lp::denoise

#pragma once
// Denoises a path-traced image with Intel Open Image Denoise's published U-Net (its `rt` filters: HDR or
// LDR colour, alone or with first-hit albedo, or with albedo and normal), run on the CPU with oneDNN.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>

#include "engine/image/image.hpp"

namespace lp::denoise {

// Which of OIDN's rt filter families: HDR (linear radiance, any range) or LDR (values in [0, 1]).
enum class Range { Hdr, Ldr };

struct DenoiseInputs {
  const Image* color = nullptr;   // required, linear RGB
  const Image* albedo = nullptr;  // optional, first-hit albedo in [0, 1], same size
  const Image* normal = nullptr;  // optional (only with albedo), first-hit normal in [-1, 1], same size
};

struct DenoiseOptions {
  Range range = Range::Hdr;
  int threads = 0;                            // 0: all of the process's threads
  float input_scale = 0;                      // 0: OIDN's autoexposure for HDR, 1 for LDR
  std::function<bool(double)> progress = {};  // fraction done; returning false cancels (DenoiseCancelled)
  int tile_size = 0;                          // 0: kDefaultTileSize; smaller tiles need less memory
};

// Bad inputs or weights.
class DenoiseError : public std::runtime_error {
  using runtime_error::runtime_error;
};
class DenoiseCancelled : public std::runtime_error {
  using runtime_error::runtime_error;
};

// The largest side of a tile the network runs on (a multiple of 16), overlaps included.
inline constexpr int kDefaultTileSize = 1152;

std::filesystem::path default_weights_dir();

class Denoiser {
 public:
  explicit Denoiser(std::filesystem::path weights_dir = default_weights_dir());
  ~Denoiser();
  Denoiser(const Denoiser&) = delete;
  Denoiser& operator=(const Denoiser&) = delete;

  const std::filesystem::path& weights_dir() const { return weights_dir_; }
  bool available() const;  // the directory has the six rt files

  // Thread-safe; loads and caches each filter's weights on first use. Tiled with overlap so that working
  // memory stays bounded whatever the image size.
  Image run(const DenoiseInputs& in, const DenoiseOptions& options = {}) const;

  // Bytes run() needs beyond the inputs and output for a width x height image (for memory admission).
  static int64_t working_bytes(int width, int height, int tile_size = kDefaultTileSize);

 private:
  struct Filters;
  std::filesystem::path weights_dir_;
  std::unique_ptr<Filters> filters_;
};

}  // namespace lp::denoise

#pragma once
// ASTC HDR compression of float images in 4x4 blocks (16 bytes each, 8 bits a texel) through Arm's
// astc-encoder (libastcenc): colour in the HDR profile, alpha 1 in LDR (astcenc's "-ch"), the format
// Vulkan calls VK_FORMAT_ASTC_4x4_SFLOAT_BLOCK and GL COMPRESSED_RGBA_ASTC_4x4_KHR with
// KHR_texture_compression_astc_hdr.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/image/image.hpp"

namespace lp {

inline constexpr int kAstcBlockSize = 4;       // texels on a side of a block
inline constexpr size_t kAstcBlockBytes = 16;  // bytes of one block

struct AstcOptions {
  // astcenc's quality, 0 (fastest) to 100 (exhaustive); its presets: 10 fast, 60 medium, 98 thorough.
  float quality = 60.0f;
  int threads = 0;  // 0: the current task arena's concurrency
};

// Bytes of the blocks covering a width x height image (an edge block is padded).
size_t astc_bytes(int width, int height);

// Compresses image after image with one set of the compressor's tables (its setup costs more than a
// small image's compression).
class AstcHdrEncoder {
 public:
  explicit AstcHdrEncoder(const AstcOptions& options = {});
  ~AstcHdrEncoder();
  AstcHdrEncoder(const AstcHdrEncoder&) = delete;
  AstcHdrEncoder& operator=(const AstcHdrEncoder&) = delete;

  // The blocks of `image`, row by row from the top. Negative and non-finite values are not representable
  // (HDR endpoints are unsigned): the caller passes radiance. Throws lp::Error(Internal) if the library
  // fails.
  std::vector<uint8_t> compress(const Image& image);

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  int threads_;
};

// The image the blocks decode to (width x height); throws lp::Error(Corrupt) on a wrong byte count.
Image decompress_astc_hdr(std::span<const uint8_t> blocks, int width, int height);

}  // namespace lp

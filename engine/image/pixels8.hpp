#pragma once
// 8-bit pictures as the encoders take them: rows top to bottom of `channels` bytes per pixel, 3 (RGB) or
// 4 (RGBA, straight alpha), tightly packed.
#include <cstdint>
#include <span>
#include <string>

#include "engine/core/error.hpp"

namespace lp {

struct Pixels8 {
  std::span<const uint8_t> bytes;
  int width = 0;
  int height = 0;
  int channels = 3;
};

// Throws lp::Error(InvalidArgument) unless the picture is non-empty, of 3 or 4 channels, and `bytes`
// holds exactly its pixels. `what` names the encoder in the message.
inline void check_pixels8(const Pixels8& p, const std::string& what) {
  if (p.width <= 0 || p.height <= 0 || (p.channels != 3 && p.channels != 4) ||
      p.bytes.size() != size_t(p.width) * size_t(p.height) * size_t(p.channels))
    throw Error(ErrorKind::InvalidArgument, what + ": expected " + std::to_string(p.width) + "x" +
                                                std::to_string(p.height) + " pixels of 3 or 4 bytes, got " +
                                                std::to_string(p.bytes.size()) + " bytes of " +
                                                std::to_string(p.channels) + " channels");
}

}  // namespace lp

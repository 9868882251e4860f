#pragma once
// WebP (lossy, libwebp) of an 8-bit picture, keeping the alpha of RGBA; and an animated WebP of frames
// of one size (libwebpmux's WebPAnimEncoder), looping forever.
#include <cstdint>
#include <vector>

#include "engine/image/pixels8.hpp"

namespace lp {

inline constexpr float kWebpQuality = 90;  // of 0..100

std::vector<uint8_t> encode_webp(const Pixels8& picture, float quality = kWebpQuality);

// Every frame is shown for 1000 / fps ms (rounded); all frames share width, height and channels.
std::vector<uint8_t> encode_webp_animation(std::span<const Pixels8> frames, int fps,
                                           float quality = kWebpQuality);

}  // namespace lp

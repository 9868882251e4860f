#pragma once
// RGBD: linear radiance in 8-bit RGBA, as Babylon.js stores the faces of its prefiltered environments
// (.env) and decodes them (its shaders rgbdEncode / rgbdDecode, toRGBD and fromRGBD). A divisor D in
// [1/255, 1] goes in A; RGB holds (colour D)^(1/2.2); the colour back is rgb^2.2 / D. D is the largest
// whole 255ths that keeps the brightest channel at or below 1 (at most 1), so values up to
// kRgbdMaxRange keep 8 bits of mantissa and brighter ones saturate at it.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/vec3.hpp"

namespace lp {

class Image;

inline constexpr float kRgbdMaxRange = 255;  // Babylon's rgbdMaxRange
inline constexpr float kRgbdGamma = 2.2f;    // Babylon's LinearEncodePowerApprox

using Rgbd8 = std::array<uint8_t, 4>;

// Negative and NaN channels count as 0.
Rgbd8 encode_rgbd(Rgb linear);
Rgb decode_rgbd(Rgbd8 rgbd);

// Every pixel of `image`, rows top to bottom: width * height * 4 bytes.
std::vector<uint8_t> encode_rgbd_pixels(const Image& image);
// The inverse of encode_rgbd_pixels; `rgba` holds width * height * 4 bytes.
Image decode_rgbd_pixels(std::span<const uint8_t> rgba, int width, int height);

}  // namespace lp

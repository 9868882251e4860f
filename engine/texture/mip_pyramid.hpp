#pragma once
// Mip levels of a texture: level 0 is the image, each next level half the size (rounded down, at
// least 1) until 1 x 1. Any size, power of two or not.
#include <cstdint>
#include <vector>

namespace lp {

// One level: `channels` floats per texel, rows top to bottom.
struct MipLevel {
  int width = 0, height = 0;
  std::vector<float> texels;
};

// The next level by an area-weighted box filter: each output texel averages the input texels it
// covers, with partly covered texels weighted by the covered fraction. Odd sizes keep the exact mean
// (each level's mean equals the input's, up to float rounding), which a 2 x 2 box cannot.
MipLevel downsample(const MipLevel& level, int channels);

// Level 0 (moved in) and every smaller level down to 1 x 1.
std::vector<MipLevel> build_mip_pyramid(MipLevel base, int channels);

}  // namespace lp

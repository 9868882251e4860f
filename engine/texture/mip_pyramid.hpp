#pragma once
// Mip levels of a texture: level 0 is the image, each next level half the size (rounded down, at
// least 1) until 1 x 1. Any size, power of two or not.
#include <cstdint>
#include <functional>
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
// The same from a level read a row at a time: `row(y, scratch)` returns row y's width x channels
// floats, in its own memory or written to `scratch` (room for one row). Only the rows an output row
// covers are held at once, so a level made on the fly (a weighted copy of a large map) never exists
// whole.
using MipRowSource = std::function<const float*(int y, float* scratch)>;
MipLevel downsample(int width, int height, int channels, const MipRowSource& row);

// Level 0 (moved in) and every smaller level down to 1 x 1.
std::vector<MipLevel> build_mip_pyramid(MipLevel base, int channels);
// The bytes of the pyramid build_mip_pyramid makes from a width x height level 0.
int64_t mip_pyramid_bytes(int64_t width, int64_t height, int channels);

}  // namespace lp

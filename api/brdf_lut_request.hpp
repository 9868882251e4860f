#pragma once
// GET /api/v1/brdf-lut query: the split-sum DFG table's size, layout and file format.
#include "api/params.hpp"
#include "engine/ibl/dfg_lut.hpp"
#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

inline constexpr Range<int64_t> kDfgLutSize{8, 256};
inline constexpr int kDefaultDfgLutSize = 128;

struct BrdfLutRequest {
  int size = kDefaultDfgLutSize;
  bool multiscatter = false;
  ImageFormat format = ImageFormat::Exr;
};

// size in [8, 256] (default 128), multiscatter=true|false (default false), format=exr|png|pfm|hdr
// (default exr).
BrdfLutRequest parse_brdf_lut_query(const Query& q);

// The table as an image: red and green the two channels, blue 0.
Image dfg_lut_image(const DfgLut& lut);
// PNG stores the channels linearly (a data texture, not a picture): 8 bits of [0, 1].
inline const ToneMap kLinearPng{0.0f, 1.0f};

}  // namespace lp::api

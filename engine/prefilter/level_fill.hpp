#pragma once
// The output stage of a prefilter: one level's convolution evaluated at every texel of a grid (any
// projection, texel_grid.hpp), rows in parallel. Each texel depends on its direction alone, so the
// result is the same whatever the thread count.
#include <cstdint>

#include "engine/image/image.hpp"
#include "engine/prefilter/lobe_convolution.hpp"
#include "engine/prefilter/prefilter_control.hpp"
#include "engine/prefilter/texel_grid.hpp"

namespace lp {

// `out` becomes grid.width x grid.height. Each row reports width * units_per_texel work units. False if
// the control asked to stop before the last row (the image is then incomplete).
bool fill_level(const LobeConvolution& convolution, const TexelGrid& grid, Image& out,
                const PrefilterControl& control, int64_t units_per_texel);

}  // namespace lp

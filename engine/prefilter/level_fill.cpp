#include "engine/prefilter/level_fill.hpp"

#include <tbb/parallel_for.h>

namespace lp {

bool fill_level(const LobeConvolution& convolution, const TexelGrid& grid, Image& out,
                const PrefilterControl& control, int64_t units_per_texel) {
  out = Image(grid.width, grid.height);
  tbb::parallel_for(0, grid.height, [&](int y) {
    if (control.stopped()) return;
    for (int x = 0; x < grid.width; ++x) out.set(x, y, convolution.radiance(grid.direction(x, y)));
    control.advance(int64_t(grid.width) * units_per_texel);
  });
  return !control.stopped();
}

}  // namespace lp

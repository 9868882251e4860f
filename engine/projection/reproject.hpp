#pragma once
// Resampling a map from one projection into another. Each output texel is the solid-angle-weighted mean
// of the source over the texel's footprint on the sphere, the source's texels being constant over their
// own areas (see projection_source.hpp): a constant map stays exactly constant, and the power of the
// source (sum of radiance times texel solid angle) is kept up to the difference between each target
// texel's solid angle and the area of its outline drawn with straight sides in the source's plane: a few
// 1e-6 of the power for maps 256 pixels wide, up to 5e-5 with a sun (tests/unit/projection_resample_test).
// Enlarging gives each texel the value of the source texel under it, blended along the source texels' edges;
// reducing averages every source texel the footprint covers, in part where it covers part.
//
// Parallel over rows (oneTBB); every texel is summed in a fixed order, so the result does not depend on
// the number of threads.
#include "engine/image/image.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

// `image` laid out in `from` (its shape must fit: projection_size), into `to` at `size`
// (projection_shape). Throws lp::Error(InvalidArgument) if the shape does not fit.
Image reproject(const Image& image, Projection from, Projection to, int size);

}  // namespace lp

#pragma once
// A lat-long map on another lat-long grid, larger or smaller: each new texel is the solid-angle mean of
// the radiance it covers, partly covered texels counting for the part covered, so the map's power (the
// integral of radiance over the sphere) is kept exactly, up to float rounding. Columns first (a share
// of a texel's width is a share of its solid angle), then rows (weighted by the exact solid angle of
// the band of theta they share).
#include <cstdint>

#include "engine/image/image.hpp"

namespace lp {

Image resample_latlong(const Image& image, int width, int height);

// The bytes resampling a map of `source_height` rows to width x height takes: the result and the map
// resampled in columns only.
int64_t resample_latlong_bytes(int source_height, int width, int height);

}  // namespace lp

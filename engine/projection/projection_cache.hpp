#pragma once
// A map's projections, built once and cached on the map (EnvMap::derived, its memory reserved from the
// map's budget and evictable): per projection and size, the cube's faces once for its strip, its cross
// and its single faces.
#include <memory>

#include "engine/envmap/envmap.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

// The map in `projection` at `size`: for Cube and Cross, the strip of the six faces (cube_layout.hpp).
std::shared_ptr<const Image> projection_cached(const EnvMap& map, Projection projection, int size);

}  // namespace lp

#pragma once
// What an EXR file of a projection's image says in OpenEXR's `envmap` attribute: a lat-long map is
// OpenEXR's latlong; our strip of cube faces, the cross and the squares are layouts OpenEXR does not
// define, so they carry none.
#include "engine/image/exr_standard_attributes.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

constexpr ExrEnvmap exr_envmap(Projection projection) {
  return projection == Projection::LatLong ? ExrEnvmap::LatLong : ExrEnvmap::None;
}

}  // namespace lp

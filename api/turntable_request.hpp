#pragma once
// The body of POST /api/v1/turntables: a render request's fields (api/render_request.hpp) and
// `turntable`, the orbit of frames (engine/render/turntable.hpp). The turntable places every frame's
// camera, so the scene gives none: `scene.camera` is refused. Every failure is a 400 naming the field.
#include "api/parameters.hpp"
#include "api/params.hpp"
#include "api/render_request.hpp"
#include "engine/render/turntable.hpp"

namespace lp::api {

// Where a frame's orbit may start and how far it may step, in degrees either way.
inline constexpr Range<double> kTurntableAzimuthDeg{-360.0, 360.0};
// The elevation's swing either way, at most the span of kElevationDeg (validate() bounds its sum with it).
inline constexpr Range<double> kTurntableSweepDeg{limits::kElevationDeg.min - limits::kElevationDeg.max,
                                                  limits::kElevationDeg.max - limits::kElevationDeg.min};

struct TurntableRequest {
  RenderRequest render;  // its scene's camera is the default one, replaced frame by frame
  render::Turntable turntable;
};

// Also refuses a turntable whose frames together hold more than `limits.max_pixels` pixels (naming
// `turntable.frames`), and an `object` that is not one of the scene's objects.
TurntableRequest parse_turntable_request(const Json& body, const RequestLimits& limits);

}  // namespace lp::api

#include "engine/render/turntable.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/validate.hpp"

namespace lp::render {

void Turntable::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "frames"), int64_t(frames), limits::kTurntableFrames);
  require_in(field_path(prefix, "margin"), margin, limits::kFitMargin);
  require_in(field_path(prefix, "elevation_deg"), elevation_deg, limits::kElevationDeg);
  const double sweep = std::abs(double(elevation_sweep_deg));
  if (!limits::kElevationDeg.contains(elevation_deg - sweep) ||
      !limits::kElevationDeg.contains(elevation_deg + sweep))
    invalid_parameter(field_path(prefix, "elevation_sweep_deg"),
                      fmt::format("takes the elevation out of [{}, {}]: {} +- {}", limits::kElevationDeg.min,
                                  limits::kElevationDeg.max, elevation_deg, sweep));
}

CameraFit turntable_fit(const Turntable& t, int index) {
  CameraFit fit;
  fit.object = t.object;
  fit.margin = t.margin;
  fit.azimuth_deg = std::remainder(t.azimuth_start_deg + float(index) * t.step_deg(), 360.0f);
  const float turn = 2.0f * kPiF * float(index) / float(t.frames);
  fit.elevation_deg = t.elevation_deg + t.elevation_sweep_deg * std::sin(turn);
  return fit;
}

std::array<float, 16> camera_to_world(const Camera& c) {
  const Vec3 back = normalize(c.position - c.look_at);  // the camera's local +z
  const Vec3 right = normalize(cross(c.up, back));      // local +x
  const Vec3 up = cross(back, right);                   // local +y
  return {right.x, up.x, back.x, c.position.x, right.y, up.y, back.y, c.position.y,
          right.z, up.z, back.z, c.position.z, 0,       0,    0,      1};
}

}  // namespace lp::render

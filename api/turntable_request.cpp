#include "api/turntable_request.hpp"

#include <fmt/format.h>

#include <limits>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "api/excerpt.hpp"

namespace lp::api {
namespace {

const std::string kField = "turntable";

render::Turntable parse_turntable(const Json& t) {
  if (!t.is_object()) throw invalid_field(kField, fmt::format("must be an object, got {}", describe(t)));
  reject_unknown_fields(t,
                        {"frames", "azimuth_start_deg", "azimuth_step_deg", "elevation_deg",
                         "elevation_sweep_deg", "margin", "object"},
                        kField);
  render::Turntable r;
  const auto& frames = limits::kTurntableFrames;
  r.frames = int(json_int(t, "frames", r.frames, frames.min, frames.max, kField));
  const auto& azimuth = kTurntableAzimuthDeg;
  r.azimuth_start_deg =
      float(json_double(t, "azimuth_start_deg", r.azimuth_start_deg, azimuth.min, azimuth.max, kField));
  if (t.contains("azimuth_step_deg") && !t["azimuth_step_deg"].is_null())
    r.azimuth_step_deg = float(json_double(t, "azimuth_step_deg", 0, azimuth.min, azimuth.max, kField));
  const auto& elevation = limits::kElevationDeg;
  r.elevation_deg =
      float(json_double(t, "elevation_deg", r.elevation_deg, elevation.min, elevation.max, kField));
  const auto& sweep = kTurntableSweepDeg;
  r.elevation_sweep_deg =
      float(json_double(t, "elevation_sweep_deg", r.elevation_sweep_deg, sweep.min, sweep.max, kField));
  const auto& margin = limits::kFitMargin;
  r.margin = float(json_double(t, "margin", r.margin, margin.min, margin.max, kField));
  if (t.contains("object") && !t["object"].is_null())
    r.object = uint32_t(json_int(t, "object", 0, 0, std::numeric_limits<uint32_t>::max(), kField));
  as_invalid_field([&] { r.validate(kField); });
  return r;
}

void check_frames_fit(const TurntableRequest& r, const RequestLimits& limits) {
  const auto& s = r.render.settings;
  const int64_t pixels = int64_t(r.turntable.frames) * s.width * s.height;
  if (pixels > limits.max_pixels)
    throw invalid_field(kField + ".frames",
                        fmt::format("{} frames of {}x{} are {} pixels together, over the limit of {} "
                                    "(--max-pixels): fewer frames or smaller ones",
                                    r.turntable.frames, s.width, s.height, pixels, limits.max_pixels));
}

void check_object(const TurntableRequest& r) {
  const auto& object = r.turntable.object;
  const size_t objects = r.render.scene.objects.size();
  if (object && *object >= objects)
    throw invalid_field(
        kField + ".object",
        fmt::format("must be the index of one of the scene's {} objects, got {}", objects, *object));
}

}  // namespace

TurntableRequest parse_turntable_request(const Json& body, const RequestLimits& limits) {
  if (!body.is_object()) throw ApiError(ErrorCode::InvalidJson, "the request body must be a JSON object");
  const auto turntable = body.find(kField);
  if (turntable == body.end()) throw invalid_field(kField, "is required");
  const auto scene = body.find("scene");
  if (scene != body.end() && scene->is_object() && scene->contains("camera"))
    throw invalid_field("scene.camera", "must not be given: the turntable places every frame's camera");
  TurntableRequest r;
  r.turntable = parse_turntable(*turntable);
  Json render = body;
  render.erase(kField);
  r.render = parse_render_request(render, limits, kTurntableDenoise);
  check_object(r);
  check_frames_fit(r, limits);
  return r;
}

}  // namespace lp::api

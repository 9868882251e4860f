#include "cli/turntable_options.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "cli/help.hpp"
#include "engine/core/limits.hpp"

namespace lp::cli {
namespace {

constexpr std::string_view kPrefix = "turntable";
// The orbit's options (without dashes) besides --turntable itself, which gives `frames`.
const std::vector<std::string_view> kOrbit = {"azimuth-start-deg", "azimuth-step-deg", "elevation-deg",
                                              "elevation-sweep-deg", "margin"};

float angle(const api::Json& fields, const std::string& name, float fallback) {
  return float(api::json_double(fields, name, fallback, -360, 360, std::string(kPrefix)));
}

}  // namespace

std::optional<render::Turntable> take_turntable(Arguments& args) {
  if (!args.has("turntable")) {
    for (const std::string_view name : kOrbit)
      if (args.has(name))
        throw api::ApiError(api::ErrorCode::BadRequest, fmt::format("--{} needs --turntable N", name));
    return std::nullopt;
  }
  api::Json fields = args.take_json(kOrbit);
  fields["frames"] = args.take_json({"turntable"})["turntable"];
  const std::string prefix(kPrefix);
  render::Turntable t;
  t.frames = int(api::json_int(fields, "frames", t.frames, limits::kTurntableFrames.min,
                               limits::kTurntableFrames.max, prefix));
  t.azimuth_start_deg = angle(fields, "azimuth_start_deg", t.azimuth_start_deg);
  if (fields.contains("azimuth_step_deg")) t.azimuth_step_deg = angle(fields, "azimuth_step_deg", 0);
  t.elevation_deg = angle(fields, "elevation_deg", t.elevation_deg);
  t.elevation_sweep_deg = angle(fields, "elevation_sweep_deg", t.elevation_sweep_deg);
  t.margin = float(
      api::json_double(fields, "margin", t.margin, limits::kFitMargin.min, limits::kFitMargin.max, prefix));
  api::as_invalid_field([&] { t.validate(prefix); });
  return t;
}

std::string turntable_help() {
  const render::Turntable d;
  return option_line(
             "--turntable N",
             fmt::format("render N frames, in [{}, {}], orbiting the framed scene about +z, into\n"
                         "the folder -o DIR: DIR/frame_0000.png ... (--format) and DIR/cameras.json,\n"
                         "each frame's camera as a turntable's status gives it",
                         limits::kTurntableFrames.min, limits::kTurntableFrames.max)) +
         option_line("--azimuth-start-deg A", fmt::format("the first frame's azimuth (default {}: from the "
                                                          "front, -y; 90: from +x)",
                                                          d.azimuth_start_deg)) +
         option_line("--azimuth-step-deg S", "the azimuth from one frame to the next (default 360 / N)") +
         option_line("--elevation-deg E",
                     fmt::format("above the horizon, in [{}, {}] (default {})", limits::kElevationDeg.min,
                                 limits::kElevationDeg.max, d.elevation_deg)) +
         option_line(
             "--elevation-sweep-deg W",
             fmt::format("the elevation swings by +-W over the turn, E + W sin(2 pi i / N) (default {})",
                         d.elevation_sweep_deg)) +
         option_line("--margin M", fmt::format("the framed radius over the view's, in [{}, {}] (default {})",
                                               limits::kFitMargin.min, limits::kFitMargin.max, d.margin));
}

}  // namespace lp::cli

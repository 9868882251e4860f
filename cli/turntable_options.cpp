#include "cli/turntable_options.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "cli/help.hpp"
#include "engine/core/limits.hpp"
#include "engine/render/turntable.hpp"

namespace lp::cli {
namespace {

// The orbit's options (without dashes) besides --turntable itself, which gives `frames`.
const std::vector<std::string_view> kOrbit = {"azimuth-start-deg", "azimuth-step-deg", "elevation-deg",
                                              "elevation-sweep-deg", "margin"};

}  // namespace

std::optional<api::Json> take_turntable(Arguments& args) {
  if (!args.has("turntable")) {
    for (const std::string_view name : kOrbit)
      if (args.has(name))
        throw api::ApiError(api::ErrorCode::BadRequest, fmt::format("--{} needs --turntable N", name));
    return std::nullopt;
  }
  api::Json turntable = args.take_json(kOrbit);
  turntable["frames"] = args.take_json({"turntable"})["turntable"];
  return turntable;
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

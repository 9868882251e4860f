#pragma once
// `--turntable N` and the options of its orbit, named as the fields of a turntable request's `turntable`
// object (--elevation-deg is elevation_deg): N frames orbiting the framed scene
// (engine/render/turntable.hpp).
#include <optional>
#include <string>

#include "cli/arguments.hpp"
#include "engine/render/turntable.hpp"

namespace lp::cli {

// Takes the options; nullopt without --turntable (an orbit option without it is a bad_request). Throws
// invalid_field naming the field (turntable.frames, ...) for a value out of its range.
std::optional<render::Turntable> take_turntable(Arguments& args);

std::string turntable_help();

}  // namespace lp::cli

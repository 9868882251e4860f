#pragma once
// `--turntable N` and the options of its orbit, named as the fields of a turntable request's `turntable`
// object (--elevation-deg is elevation_deg): N frames orbiting the framed scene
// (engine/render/turntable.hpp).
#include <optional>
#include <string>

#include "cli/arguments.hpp"

namespace lp::cli {

// Takes the options, as the `turntable` object of a turntable request (api/turntable_request.hpp, which
// checks it); nullopt without --turntable (an orbit option without it is a bad_request).
std::optional<api::Json> take_turntable(Arguments& args);

std::string turntable_help();

}  // namespace lp::cli

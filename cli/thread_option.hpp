#pragma once
// The --threads option of commands that compute: api::kThreads' name, range and help.
#include <string>

#include "cli/arguments.hpp"

namespace lp::cli {

// Takes --threads; 0 when not given (all cores).
int take_threads(Arguments& args);

// Its --help line.
std::string threads_help();

}  // namespace lp::cli

#pragma once
// The names --log-level accepts, each mapped to its spdlog level.
#include <spdlog/common.h>

#include <string>

namespace lp::server {

// "trace", "debug", "info", "warn", "error" or "off"; throws std::invalid_argument listing them.
spdlog::level::level_enum parse_log_level(const std::string& name);
// The accepted names, "trace|debug|...", for --help and messages.
std::string log_level_names();

}  // namespace lp::server

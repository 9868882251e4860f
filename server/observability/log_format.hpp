#pragma once
// How log lines are written (--log-format): text for people, or one JSON object a line for a log
// collector (logging.hpp).
#include "engine/core/enum_table.hpp"

namespace lp::server {

enum class LogFormat { Text, Json };

constexpr auto enum_entries(LogFormat) {
  return std::to_array<EnumEntry<LogFormat>>({{LogFormat::Text, "text"}, {LogFormat::Json, "json"}});
}

}  // namespace lp::server

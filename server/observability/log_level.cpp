#include "server/observability/log_level.hpp"

#include <array>
#include <stdexcept>
#include <utility>

namespace lp::server {
namespace {

using spdlog::level::level_enum;

constexpr std::array<std::pair<const char*, level_enum>, 6> kLevels = {{
    {"trace", level_enum::trace},
    {"debug", level_enum::debug},
    {"info", level_enum::info},
    {"warn", level_enum::warn},
    {"error", level_enum::err},
    {"off", level_enum::off},
}};

}  // namespace

level_enum parse_log_level(const std::string& name) {
  for (const auto& [text, level] : kLevels)
    if (name == text) return level;
  throw std::invalid_argument("--log-level takes one of " + log_level_names() + ", got '" + name + "'");
}

std::string log_level_names() {
  std::string names;
  for (const auto& [text, level] : kLevels) {
    if (!names.empty()) names += '|';
    names += text;
  }
  return names;
}

}  // namespace lp::server

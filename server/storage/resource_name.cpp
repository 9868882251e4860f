#include "server/storage/resource_name.hpp"

#include <regex>

namespace lp::server {

bool valid_resource_name(const std::string& name) {
  static const std::regex pattern(R"([A-Za-z0-9_-][A-Za-z0-9._-]{0,63})");
  return std::regex_match(name, pattern);
}

}  // namespace lp::server

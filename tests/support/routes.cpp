#include "support/routes.hpp"

#include <cstdio>
#include <regex>
#include <stdexcept>

namespace lp::test {

std::vector<ListedRoute> registered_routes() {
  const std::string cmd = std::string(LIGHTPROBE_SERVER_BIN) + " --list-routes";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + cmd);
  std::vector<ListedRoute> routes;
  char method[16], path[512];
  while (fscanf(pipe, "%15s %511s", method, path) == 2) routes.push_back({method, path});
  if (pclose(pipe) != 0) throw std::runtime_error(cmd + " failed");
  return routes;
}

std::string fill_path(const std::string& path, const std::string& value) {
  static const std::regex parameter(R"(\{[^}/]+\})");
  return std::regex_replace(path, parameter, value);
}

}  // namespace lp::test

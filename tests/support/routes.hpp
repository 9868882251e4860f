#pragma once
// The routes the real server binary registers, as `lightprobe-server --list-routes` prints them.
#include <string>
#include <vector>

namespace lp::test {

struct ListedRoute {
  std::string method;  // GET, POST, DELETE
  std::string path;    // OpenAPI form, e.g. /api/v1/envmaps/{id}
};

std::vector<ListedRoute> registered_routes();

// `path` with every {parameter} segment replaced by `value`.
std::string fill_path(const std::string& path, const std::string& value);

}  // namespace lp::test

#pragma once
// POST /api/v1/envmaps with a JSON body: {"name": "studio", "path": "studio.hdr"}, both required. The
// server checks the name and resolves the path inside its data directory.
#include <string>

namespace lp::api {

struct EnvMapLoadRequest {
  std::string name;
  std::string path;  // relative to --data-dir
};

EnvMapLoadRequest parse_envmap_load_request(const std::string& body);

}  // namespace lp::api

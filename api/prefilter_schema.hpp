#pragma once
// What a prefilter job's status says about its chain: the map, the parameters, every level's size and
// roughness, the conventions, and its files (their URLs under `files_url`, fetchable once it is done).
#include <string>
#include <vector>

#include "api/bake/bake_target.hpp"
#include "api/params.hpp"
#include "api/prefilter_request.hpp"

namespace lp::api {

struct PrefilterDescription {
  std::string envmap;
  std::string files_url;  // "/api/v1/prefilters/{id}/files"
  bool done = false;
  int source_width = 0;  // the width of the map the lobes read, once known
  // A target's files, once written (a request with a target lists these instead of the chain's).
  const std::vector<BakeFile>* target_files = nullptr;
};

void describe_prefilter(Json& out, const PrefilterRequest& request, const PrefilterDescription& d);

}  // namespace lp::api

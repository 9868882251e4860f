#pragma once
// What a prefilter job's status says about its chain: the map, the parameters, every level's size and
// roughness, the conventions, and its files (their URLs under `files_url`, fetchable once it is done).
#include <string>

#include "api/params.hpp"
#include "api/prefilter_request.hpp"

namespace lp::api {

struct PrefilterDescription {
  std::string envmap;
  std::string files_url;  // "/api/v1/prefilters/{id}/files"
  bool done = false;
  int source_width = 0;  // the width of the map the lobes read, once known
};

void describe_prefilter(Json& out, const PrefilterRequest& request, const PrefilterDescription& d);

}  // namespace lp::api

#pragma once
// Every endpoint accepts exactly the query parameters api/openapi.yaml declares for it, each at most
// once: anything else is a 400 naming the parameter, so a typo is never silently ignored.
#include <string>
#include <vector>

#include "api/params.hpp"

namespace lp::api {

class QueryPolicy {
 public:
  // The parameters documented for `method` on `path` (OpenAPI form); throws if it is not documented.
  QueryPolicy(const std::string& method, const std::string& path);

  // Throws ApiError 400 "invalid_field" naming the first unknown or repeated parameter.
  void check(const Query& params) const;

 private:
  std::vector<std::string> accepted_;
};

}  // namespace lp::api

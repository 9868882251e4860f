#include "api/query_policy.hpp"

#include <algorithm>

#include "api/api_error.hpp"
#include "api/openapi_parameters.hpp"

namespace lp::api {

QueryPolicy::QueryPolicy(const std::string& method, const std::string& path)
    : accepted_(documented_query_parameters(method, path)) {}

void QueryPolicy::check(const Query& params) const {
  for (const auto& [name, value] : params) {
    if (std::find(accepted_.begin(), accepted_.end(), name) == accepted_.end())
      throw invalid_field(name, accepted_.empty()
                                    ? "unknown parameter (this endpoint takes no query parameters)"
                                    : "unknown parameter (expected one of: " + join(accepted_, ", ") + ")");
    if (params.count(name) > 1) throw invalid_field(name, "given more than once");
  }
}

}  // namespace lp::api

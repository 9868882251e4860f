#include "server/query_policy.hpp"

#include <algorithm>

#include "api/api_error.hpp"
#include "api/openapi_parameters.hpp"
#include "api/params.hpp"

namespace lp::server {

QueryPolicy::QueryPolicy(const std::string& method, const std::string& path)
    : accepted_(api::documented_query_parameters(method, path)) {}

void QueryPolicy::check(const httplib::Params& params) const {
  for (const auto& [name, value] : params) {
    if (std::find(accepted_.begin(), accepted_.end(), name) == accepted_.end())
      throw api::invalid_field(
          name, accepted_.empty()
                    ? "unknown parameter (this endpoint takes no query parameters)"
                    : "unknown parameter (expected one of: " + api::join(accepted_, ", ") + ")");
    if (params.count(name) > 1) throw api::invalid_field(name, "given more than once");
  }
}

}  // namespace lp::server

#include "server/http/method_policy.hpp"

#include <algorithm>

#include "api/excerpt.hpp"
#include "api/params.hpp"

namespace lp::server {

bool refuse_method(const Router& router, const httplib::Request& req, httplib::Response& res) {
  std::vector<std::string> allowed = router.methods_for(req.path);
  const auto get = std::find(allowed.begin(), allowed.end(), "GET");
  if (get != allowed.end()) allowed.insert(get + 1, "HEAD");
  if (allowed.empty() || std::find(allowed.begin(), allowed.end(), req.method) != allowed.end()) return false;
  const std::string list = api::join(allowed, ", ");
  res.set_header("Allow", list);
  send_error(
      res, api::ErrorCode::MethodNotAllowed,
      api::excerpt(req.method) + " is not allowed on " + api::excerpt(req.path) + " (allowed: " + list + ")");
  return true;
}

}  // namespace lp::server

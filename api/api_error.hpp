#pragma once
// The error every handler may throw; the router turns it into
// {"error":{"code":"...","message":"..."}} with `status`.
#include <stdexcept>
#include <string>

#include "api/excerpt.hpp"

namespace lp::api {

class ApiError : public std::runtime_error {
 public:
  ApiError(int status, std::string code, const std::string& message)
      : std::runtime_error(message), status_(status), code_(std::move(code)) {}
  int status() const { return status_; }
  const std::string& code() const { return code_; }

 private:
  int status_;
  std::string code_;
};

// 400 naming the offending field: "invalid_field", "field 'count': must be ...". Field names may come
// from the client (unknown keys), so they are excerpted too.
inline ApiError invalid_field(const std::string& field, const std::string& problem) {
  return ApiError(400, "invalid_field", "field '" + excerpt(field) + "': " + problem);
}
inline ApiError not_found(const std::string& what) {
  return ApiError(404, "not_found", what);
}

}  // namespace lp::api

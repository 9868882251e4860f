#pragma once
// The error every handler may throw; the router turns it into
// {"error":{"code":"...","message":"..."}} with the code's status (api/error_codes.hpp).
#include <stdexcept>
#include <string>

#include "api/error_codes.hpp"
#include "api/excerpt.hpp"

namespace lp::api {

class ApiError : public std::runtime_error {
 public:
  ApiError(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const { return code_; }
  int status() const { return http_status(code_); }

 private:
  ErrorCode code_;
};

// 400 naming the offending field: "invalid_field", "field 'count': must be ...". Field names may come
// from the client (unknown keys), so they are excerpted too.
inline ApiError invalid_field(const std::string& field, const std::string& problem) {
  return ApiError(ErrorCode::InvalidField, "field '" + excerpt(field) + "': " + problem);
}
inline ApiError not_found(const std::string& what) {
  return ApiError(ErrorCode::NotFound, what);
}

}  // namespace lp::api

#pragma once
// Responses the transport writes itself, before or instead of httplib: the JSON error shape, and the
// connection closed after them.
#include <string>

#include "api/error_codes.hpp"

namespace lp::server {

// A complete HTTP/1.1 response with {"error":{"code":..,"message":..,"request_id":..}} (a new id, also in
// X-Request-Id) and Connection: close;
// `extra_headers` are whole header lines, each ending in \r\n.
std::string raw_error_response(api::ErrorCode code, const std::string& message,
                               const std::string& extra_headers = {});

}  // namespace lp::server

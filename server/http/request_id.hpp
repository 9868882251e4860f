#pragma once
// Every request has an id, answered in its X-Request-Id header, written in its access log line and in
// the body of an error: the client's own X-Request-Id when it is a safe one (so a request can be followed
// through a proxy that set it), else a new one.
#include <httplib.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace lp::server {

inline constexpr size_t kMaxRequestIdLength = 128;
inline constexpr const char* kRequestIdHeader = "X-Request-Id";

// 1 to kMaxRequestIdLength characters of A-Z, a-z, 0-9, '-', '_', '.' and ':'.
bool is_safe_request_id(std::string_view id);
// 16 random hex digits.
std::string new_request_id();
// The client's X-Request-Id if it is safe, else a new id.
std::string request_id_for(const httplib::Request& req);

}  // namespace lp::server

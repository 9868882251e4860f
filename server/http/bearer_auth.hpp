#pragma once
// --auth-token-file: when set, every API route but the probes (/api/v1/health, /api/v1/ready), and
// /metrics, needs `Authorization: Bearer <token>`; others get 401 unauthorized with WWW-Authenticate
// (RFC 6750). The token is compared in constant time. The dashboard's static files and CORS preflights
// (which a browser sends without credentials) need none.
#include <httplib.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace lp::server {

inline constexpr size_t kMinAuthTokenLength = 16;

// The token in `file`: surrounding white space (a final line break) trimmed, at least kMinAuthTokenLength
// characters of A-Z a-z 0-9 - . _ ~ + / (then = padding), RFC 6750's token. Throws std::invalid_argument
// saying what is wrong.
std::string read_auth_token(const std::filesystem::path& file);

// Whether `given` equals `expected`, in a time that depends on expected's length only.
bool constant_time_equal(std::string_view given, std::string_view expected);

class BearerAuth {
 public:
  explicit BearerAuth(std::string token) : token_(std::move(token)) {}  // empty: no token needed

  // Whether a request for `path` needs the token (when one is set).
  static bool guards(std::string_view path);
  // For a request that needs the token and does not carry it: answers 401 (true). False: it may pass.
  bool refuse(const httplib::Request& req, httplib::Response& res) const;

 private:
  std::string token_;
};

}  // namespace lp::server

#include "server/http/bearer_auth.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "server/http/probe_routes.hpp"
#include "server/http/responses.hpp"

namespace lp::server {
namespace {

constexpr const char* kChallenge = "Bearer realm=\"lightprobe\"";

bool is_token_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '~' ||
         c == '+' || c == '/';
}

// RFC 6750's b64token: token characters, then any '=' padding.
bool is_b64token(std::string_view s) {
  const size_t end = s.find_last_not_of('=');
  return end != std::string_view::npos &&
         std::all_of(s.begin(), s.begin() + std::ptrdiff_t(end + 1), is_token_char);
}

// The credentials of "Bearer <token>" (the scheme in any case), or nullopt for another header.
std::optional<std::string_view> bearer_credentials(std::string_view header) {
  constexpr std::string_view scheme = "bearer ";
  if (header.size() <= scheme.size() ||
      !std::equal(scheme.begin(), scheme.end(), header.begin(),
                  [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); }))
    return std::nullopt;
  header.remove_prefix(scheme.size());
  while (!header.empty() && header.front() == ' ') header.remove_prefix(1);
  return header;
}

}  // namespace

std::string read_auth_token(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("--auth-token-file: cannot read {}", file.string()));
  std::string token{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  token.erase(0, token.find_first_not_of(" \t\r\n"));
  token.erase(token.find_last_not_of(" \t\r\n") + 1);
  if (token.size() < kMinAuthTokenLength || !is_b64token(token))
    throw std::invalid_argument(fmt::format(
        "--auth-token-file: {} must hold one token of at least {} characters of A-Z a-z 0-9 - . _ ~ + / "
        "(then = padding), e.g. made by `openssl rand -hex 32`",
        file.string(), kMinAuthTokenLength));
  return token;
}

bool constant_time_equal(std::string_view given, std::string_view expected) {
  volatile unsigned char diff = given.size() == expected.size() ? 0 : 1;
  for (size_t i = 0; i < expected.size(); ++i)
    diff = diff | static_cast<unsigned char>(expected[i] ^ (i < given.size() ? given[i] : 0));
  return diff == 0;
}

bool BearerAuth::guards(std::string_view path) {
  return (is_api_path(path) && !is_probe(path)) || path == "/metrics";
}

bool BearerAuth::refuse(const httplib::Request& req, httplib::Response& res) const {
  if (token_.empty() || !guards(req.path)) return false;
  const std::string authorization = req.get_header_value("Authorization");
  const auto given = bearer_credentials(authorization);
  if (given && constant_time_equal(*given, token_)) return false;
  if (given) {
    res.set_header("WWW-Authenticate", std::string(kChallenge) + ", error=\"invalid_token\"");
    send_error(res, api::ErrorCode::Unauthorized, "the bearer token is not this server's");
  } else {
    res.set_header("WWW-Authenticate", kChallenge);
    send_error(res, api::ErrorCode::Unauthorized,
               "this server needs a token: send Authorization: Bearer <the token of its --auth-token-file>");
  }
  return true;
}

}  // namespace lp::server

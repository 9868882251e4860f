#include "server/scale_out/redis_url.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <iterator>
#include <stdexcept>
#include <string_view>

namespace lp::server {
namespace {

constexpr size_t kMaxUrlLength = 1024;
constexpr std::string_view kPlain = "redis://", kTls = "rediss://";

bool unreserved(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '~';
}

std::string percent_encoded(std::string_view text) {
  std::string out;
  for (const char c : text)
    if (unreserved(c))
      out += c;
    else
      fmt::format_to(std::back_inserter(out), "%{:02X}", static_cast<unsigned char>(c));
  return out;
}

std::optional<std::string> percent_decoded(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    unsigned value = 0;
    if (text.size() - i < 3) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data() + i + 1, text.data() + i + 3, value, 16);
    if (ec != std::errc() || end != text.data() + i + 3) return std::nullopt;
    out += char(value);
    i += 2;
  }
  return out;
}

bool host_name(std::string_view host) {
  if (host.empty() || host.size() > 253) return false;
  for (const char c : host)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') return false;
  return true;
}

bool ipv6_text(std::string_view host) {
  if (host.size() < 2 || host.size() > 45) return false;
  for (const char c : host)
    if (!std::isxdigit(static_cast<unsigned char>(c)) && c != ':' && c != '.') return false;
  return host.find(':') != std::string_view::npos;
}

// An integer of digits only in [min, max].
std::optional<int> number(std::string_view text, int min, int max) {
  int value = 0;
  if (text.empty() || text.size() > 9) return std::nullopt;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max)
    return std::nullopt;
  return value;
}

// [HOST] or HOST, then :PORT if any.
bool parse_host_port(std::string_view text, RedisAddress& address) {
  std::string_view port;
  if (text.starts_with('[')) {
    const size_t close = text.find(']');
    if (close == std::string_view::npos) return false;
    address.host = text.substr(1, close - 1);
    if (!ipv6_text(address.host)) return false;
    text.remove_prefix(close + 1);
    if (!text.empty() && !text.starts_with(':')) return false;
    port = text.empty() ? text : text.substr(1);
    if (!text.empty() && port.empty()) return false;
  } else {
    const size_t colon = text.find(':');
    address.host = text.substr(0, colon);
    if (!host_name(address.host)) return false;
    if (colon != std::string_view::npos) {
      port = text.substr(colon + 1);
      if (port.empty()) return false;
    }
  }
  if (port.empty()) return true;
  const auto value = number(port, 1, 65535);
  if (!value) return false;
  address.port = *value;
  return true;
}

// USER:PASSWORD, USER, or :PASSWORD, percent-decoded.
bool parse_user_info(std::string_view text, RedisAddress& address) {
  const size_t colon = text.find(':');
  const auto user = percent_decoded(text.substr(0, colon));
  if (!user) return false;
  address.user = *user;
  if (colon == std::string_view::npos) return !address.user.empty();
  address.password = percent_decoded(text.substr(colon + 1));
  return address.password && !address.password->empty();
}

std::optional<RedisAddress> parse(std::string_view url) {
  RedisAddress address;
  address.tls = url.starts_with(kTls);
  if (!address.tls && !url.starts_with(kPlain)) return std::nullopt;
  url.remove_prefix(address.tls ? kTls.size() : kPlain.size());
  const size_t slash = url.find('/');
  std::string_view authority = url.substr(0, slash);
  const std::string_view path = slash == std::string_view::npos ? "" : url.substr(slash + 1);
  if (const size_t at = authority.rfind('@'); at != std::string_view::npos) {
    if (!parse_user_info(authority.substr(0, at), address)) return std::nullopt;
    authority.remove_prefix(at + 1);
  }
  if (!parse_host_port(authority, address)) return std::nullopt;
  if (!path.empty()) {
    const auto db = number(path, 0, kMaxRedisDb);
    if (!db) return std::nullopt;
    address.db = *db;
  }
  return address;
}

}  // namespace

std::string RedisAddress::url() const {
  const std::string scheme(tls ? kTls : kPlain);
  std::string login;
  if (!user.empty() || password) login = percent_encoded(user) + (password ? ":***@" : "@");
  const std::string where = host.find(':') == std::string::npos ? fmt::format("{}:{}", host, port)
                                                                : fmt::format("[{}]:{}", host, port);
  return scheme + login + where + (db != 0 ? "/" + std::to_string(db) : "");
}

std::string redacted_url(const std::string& url) {
  const size_t scheme = url.find("://");
  const size_t at = url.rfind('@');
  if (scheme == std::string::npos || at == std::string::npos || at < scheme) return url;
  return fmt::format("{}***{}", std::string_view(url).substr(0, scheme + 3),
                     std::string_view(url).substr(at));
}

RedisAddress parse_redis_url(const std::string& url) {
  std::optional<RedisAddress> address;
  if (url.size() <= kMaxUrlLength) address = parse(url);
  if (!address)
    throw std::invalid_argument(
        fmt::format("--redis takes a URL redis://[USER:PASSWORD@]HOST[:PORT][/DB] (rediss:// for TLS), "
                    "the user and password percent-encoded, got '{}'",
                    redacted_url(url)));
  return *address;
}

}  // namespace lp::server

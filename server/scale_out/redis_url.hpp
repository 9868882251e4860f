#pragma once
// Where Redis listens and how to log in, as --redis gives it:
// redis://[USER:PASSWORD@]HOST[:PORT][/DB], or rediss:// for TLS. The password may also come from
// --redis-password-file or LIGHTPROBE_REDIS_PASSWORD (options.cpp); it is never printed.
#include <optional>
#include <string>

namespace lp::server {

inline constexpr int kRedisDefaultPort = 6379;

// The files of a TLS connection (--redis-tls-*); empty: the system's CA store, no client certificate.
struct RedisTlsFiles {
  std::string ca;    // PEM certificates of the CAs trusted to sign the server's
  std::string cert;  // PEM client certificate (chain), for servers that verify clients
  std::string key;   // its PEM private key
};

struct RedisAddress {
  std::string host;  // an IPv6 address without its brackets
  int port = kRedisDefaultPort;
  bool tls = false;                     // rediss://
  std::string user;                     // empty: the default user (AUTH PASSWORD)
  std::optional<std::string> password;  // none: no AUTH
  int db = 0;                           // SELECT DB on every connection when not 0
  RedisTlsFiles tls_files;
  // redis[s]://[USER:***@]HOST:PORT[/DB]: the password never appears, the user percent-encoded.
  std::string url() const;
};

// The most a database number may be (Redis's own bound is its `databases` setting).
inline constexpr int kMaxRedisDb = 1 << 20;

// Parses the URL, percent-decoding the user and password. Throws std::invalid_argument naming the form
// for anything else (other schemes, a path other than a database number, ports outside 1..65535, bad
// percent escapes); the message shows the URL without what stood before its '@'.
RedisAddress parse_redis_url(const std::string& url);

// The URL as it may be shown: anything between "://" and the last '@' replaced with "***".
std::string redacted_url(const std::string& url);

}  // namespace lp::server

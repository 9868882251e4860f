#pragma once
// One connection to Redis: a TCP socket of our own, TLS over it for rediss:// (OpenSSL: the server's
// certificate verified against --redis-tls-ca or the system's CA store, and its host name or address
// checked), commands encoded and replies decoded by hiredis (redisFormatCommandArgv, redisReader).
//
// hiredis allocates an array's table of element pointers from the array's header, before any element
// arrives, so a header of a few bytes could ask for gigabytes. Every reader here (a connection's, and
// parse_reply's in redis_client.hpp) refuses an array of more than kMaxRedisArrayElements before that.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "server/scale_out/redis_reply.hpp"
#include "server/scale_out/redis_url.hpp"

struct redisReply;
struct redisReader;
struct ssl_ctx_st;
struct ssl_st;

namespace lp::server {

// The most elements an array in a reply may have. The largest the commands of RedisClient get back are
// a render's items stream (XRANGE, read in pages of a sixteenth of this: a render can have 16 M items,
// --max-render-spp over --redis-item-spp), its notices since the last read (XREAD, every half second),
// the renders with items out (SMEMBERS: a few per server) and the items workers hold (XPENDING;
// XREADGROUP and XAUTOCLAIM ask for one). 1 M is far above each, and keeps a table at 8 MB of pointers
// whatever the server answers (64 MB for tables nested the 8 levels deep hiredis allows).
inline constexpr int kMaxRedisArrayElements = 1 << 20;

// Redis could not be reached, answered a command with an error, or with an array over
// kMaxRedisArrayElements.
class RedisError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A failure that trying again would not cure: a certificate or a password refused, a database that
// does not exist, an array over the bound.
class RedisRefusal : public RedisError {
 public:
  using RedisError::RedisError;
};

using RedisReplyPtr = std::unique_ptr<redisReply, void (*)(void*)>;
using RedisReaderPtr = std::unique_ptr<redisReader, void (*)(redisReader*)>;

// A hiredis reader refusing arrays over kMaxRedisArrayElements, writing a refused count to *refused
// (when not null).
RedisReaderPtr bounded_reader(int* refused);
// hiredis's reply as ours (error replies become Type::Nil: check the type of the raw reply first).
RedisReply copy_reply(const redisReply& reply);

// The TLS settings of every connection of a client: its trusted CAs and client certificate.
using TlsContext = std::shared_ptr<ssl_ctx_st>;
// Throws RedisRefusal naming the file that cannot be read.
TlsContext make_tls_context(const RedisTlsFiles& files);

class RedisConnection {
 public:
  // Connects within `connect_timeout` (TLS handshake included), later reads and writes each within
  // `io_timeout`. Throws RedisError when Redis cannot be reached, RedisRefusal when its certificate is
  // refused. `tls` is needed for address.tls.
  RedisConnection(const RedisAddress& address, const TlsContext& tls,
                  std::chrono::milliseconds connect_timeout, std::chrono::milliseconds io_timeout);
  ~RedisConnection();
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  // Sends the command and reads its reply; nullptr when the connection failed (then unusable, `failure`
  // says why). Throws RedisRefusal for an array over the bound (the connection then unusable).
  RedisReplyPtr exchange(const std::vector<std::string_view>& args);
  const std::string& failure() const { return failure_; }

 private:
  bool send_all(const char* data, size_t size);
  long receive(char* data, size_t size);
  void fail(std::string why);

  const std::string url_;
  int fd_ = -1;
  ssl_st* ssl_ = nullptr;
  int refused_elements_ = 0;
  RedisReaderPtr reader_;
  std::string failure_;
};

}  // namespace lp::server

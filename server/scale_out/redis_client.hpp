#pragma once
// A connection to Redis (redis_connection.hpp), with the commands a render split over machines needs. A lost
// connection (Redis restarting, a network blip) is opened again with backoff (0.1 s doubling to 2 s) and
// the command sent again, for up to `retry_for`; then RedisError. Commands that may run twice this way are
// harmless twice in how they are used (a partial is keyed by its range, notices are deduplicated).
// Thread-safe (one command at a time).
//
// AUTH (with the user when there is one) and SELECT of the database run on every connection, the first
// and every one opened again. A failure that trying again would not cure (RedisRefusal: a certificate, a
// password or a database refused, an array over kMaxRedisArrayElements) is thrown at once, naming the
// server (never its password); a command answered with an array over the bound drops its connection (the
// rest of the reply is unread).
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/scale_out/redis_connection.hpp"
#include "server/scale_out/redis_reply.hpp"
#include "server/scale_out/redis_url.hpp"

namespace lp::server {

// The first reply in `wire`, bytes of the Redis protocol read as a connection reads them; nullopt when
// they hold no whole reply or are no such bytes, or when an array's count exceeds
// kMaxRedisArrayElements (refused as a connection's reader refuses it, before its table is allocated).
std::optional<RedisReply> parse_reply(std::string_view wire);

class RedisClient {
 public:
  explicit RedisClient(RedisAddress address, std::chrono::milliseconds retry_for = std::chrono::seconds(60));
  ~RedisClient();
  RedisClient(const RedisClient&) = delete;
  RedisClient& operator=(const RedisClient&) = delete;

  // Any command, its arguments binary safe. Throws RedisError for an error reply.
  RedisReply command(const std::vector<std::string_view>& args);

  void set(std::string_view key, std::string_view value, std::optional<int> expire_s = std::nullopt);
  void set_if_absent(std::string_view key, std::string_view value);  // SET key value NX
  void expire(std::string_view key, int seconds);
  std::optional<std::string> get(std::string_view key);
  bool exists(std::string_view key);
  void del(const std::vector<std::string_view>& keys);
  void hset(std::string_view key, std::string_view field, std::string_view value);
  std::optional<std::string> hget(std::string_view key, std::string_view field);
  void hdel(std::string_view key, std::string_view field);
  void sadd(std::string_view key, std::string_view member);
  void srem(std::string_view key, std::string_view member);
  std::vector<std::string> smembers(std::string_view key);

  // XADD key * field value ...; the new entry's id.
  std::string xadd(std::string_view key, const std::vector<std::pair<std::string, std::string>>& fields);
  // XGROUP CREATE key group start MKSTREAM; a group that exists already is left as it is. From start
  // "0" the group delivers the stream's entries from the first, from "$" only entries added later.
  void xgroup_create(std::string_view key, std::string_view group, std::string_view start = "0");
  // The entries of a stream (XRANGE key - +, read in pages).
  std::vector<StreamEntry> xrange(std::string_view key);
  // The ids of up to `count` entries delivered to the group's consumers and not acknowledged.
  std::vector<std::string> xpending(std::string_view key, std::string_view group, int64_t count);
  // Up to `count` entries delivered to the group's consumers, not acknowledged and idle for `min_idle`
  // (XPENDING key group IDLE min_idle - + count), with their consumers.
  std::vector<PendingItem> xpending_idle(std::string_view key, std::string_view group,
                                         std::chrono::milliseconds min_idle, int64_t count);
  // XCLAIM key group consumer min_idle id: the entry, if it was still idle for `min_idle` (no other
  // consumer claimed it first) and is still in the stream.
  std::vector<StreamEntry> xclaim(std::string_view key, std::string_view group, std::string_view consumer,
                                  std::chrono::milliseconds min_idle, std::string_view id);
  // The id of the last entry the group delivered; nullopt when the stream or the group is gone.
  std::optional<std::string> xgroup_last_delivered(std::string_view key, std::string_view group);
  // XREADGROUP GROUP group consumer COUNT 1 BLOCK block STREAMS keys... > ...
  std::vector<StreamEntry> xreadgroup(std::string_view group, std::string_view consumer,
                                      const std::vector<std::string>& keys, std::chrono::milliseconds block);
  // XREAD BLOCK block STREAMS key after: the entries after id `after` (without waiting when block is 0).
  std::vector<StreamEntry> xread(std::string_view key, std::string_view after,
                                 std::chrono::milliseconds block);
  void xack(std::string_view key, std::string_view group, std::string_view id);
  // XAUTOCLAIM key group consumer min_idle 0-0 COUNT 1: an entry another consumer has held for `min_idle`.
  std::vector<StreamEntry> xautoclaim(std::string_view key, std::string_view group, std::string_view consumer,
                                      std::chrono::milliseconds min_idle);

 private:
  void connect();  // throws RedisError, or RedisRefusal for a refused login
  std::optional<RedisReply> try_command(const std::vector<std::string_view>& args);

  const RedisAddress address_;
  const std::chrono::milliseconds retry_for_;
  std::mutex mutex_;
  TlsContext tls_;  // for rediss://, made at the first connection
  std::unique_ptr<RedisConnection> connection_;
};

}  // namespace lp::server

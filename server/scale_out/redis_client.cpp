#include "server/scale_out/redis_client.hpp"

#include <fmt/format.h>
#include <hiredis/hiredis.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <iterator>
#include <thread>

namespace lp::server {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr auto kConnectTimeout = 2s;
// Longer than any BLOCK the callers ask for, so a blocked read is not taken for a lost connection.
constexpr auto kCommandTimeout = 15s;
constexpr auto kFirstBackoff = 100ms, kMaxBackoff = 2000ms;
// Entries per XRANGE reply: a render's items stream can hold 16 M (--max-render-spp over
// --redis-item-spp), and one reply of them would take gigabytes.
constexpr size_t kRangePage = kMaxRedisArrayElements / 16;

std::string ms(std::chrono::milliseconds d) {
  return std::to_string(d.count());
}

}  // namespace

std::optional<RedisReply> parse_reply(std::string_view wire) {
  const RedisReaderPtr reader = bounded_reader(nullptr);
  if (redisReaderFeed(reader.get(), wire.data(), wire.size()) != REDIS_OK) return std::nullopt;
  void* raw = nullptr;
  if (redisReaderGetReply(reader.get(), &raw) != REDIS_OK || !raw) return std::nullopt;
  const RedisReplyPtr reply(static_cast<redisReply*>(raw), freeReplyObject);
  return copy_reply(*reply);
}

RedisClient::RedisClient(RedisAddress address, std::chrono::milliseconds retry_for)
    : address_(std::move(address)), retry_for_(retry_for) {}

RedisClient::~RedisClient() = default;

// Opens the connection and logs in: AUTH [USER] PASSWORD, SELECT DB.
void RedisClient::connect() {
  if (address_.tls && !tls_) tls_ = make_tls_context(address_.tls_files);
  auto connection = std::make_unique<RedisConnection>(address_, tls_, kConnectTimeout, kCommandTimeout);
  const auto login = [&](const std::vector<std::string_view>& args, const std::string& what) {
    const RedisReplyPtr reply = connection->exchange(args);
    if (!reply)
      throw RedisError(fmt::format("cannot {} at {}: {}", what, address_.url(), connection->failure()));
    if (reply->type == REDIS_REPLY_ERROR)
      throw RedisRefusal(
          fmt::format("{} refused by {}: {}", what, address_.url(), std::string(reply->str, reply->len)));
  };
  if (address_.password) {
    if (address_.user.empty())
      login({"AUTH", *address_.password}, "AUTH");
    else
      login({"AUTH", address_.user, *address_.password}, "AUTH as user " + address_.user);
  }
  if (address_.db != 0)
    login({"SELECT", std::to_string(address_.db)}, "SELECT " + std::to_string(address_.db));
  connection_ = std::move(connection);
}

// The reply on the open connection, nullopt when the connection failed (then dropped); throws
// RedisError for an error reply other than LOADING (Redis reading its append-only file after a restart:
// try again), and RedisRefusal for an array over the bound (the connection dropped).
std::optional<RedisReply> RedisClient::try_command(const std::vector<std::string_view>& args) {
  const std::string_view name = args.empty() ? "" : args[0];
  RedisReplyPtr reply(nullptr, freeReplyObject);
  try {
    reply = connection_->exchange(args);
  } catch (const RedisRefusal& e) {
    connection_.reset();  // the rest of the reply is unread
    const std::string what = fmt::format("redis {}: {}; connection dropped", name, e.what());
    spdlog::warn("{}", what);
    throw RedisRefusal(what);
  }
  if (!reply) {
    spdlog::debug("redis {}: {}", address_.url(), connection_->failure());
    connection_.reset();
    return std::nullopt;
  }
  if (reply->type == REDIS_REPLY_ERROR) {
    const std::string message(reply->str, reply->len);
    if (message.starts_with("LOADING")) return std::nullopt;
    throw RedisError(fmt::format("redis {}: {}", name, message));
  }
  return copy_reply(*reply);
}

RedisReply RedisClient::command(const std::vector<std::string_view>& args) {
  std::lock_guard lock(mutex_);
  const auto deadline = Clock::now() + retry_for_;
  auto backoff = std::chrono::milliseconds(kFirstBackoff);
  std::string last_failure = "no answer";
  for (;;) {
    try {
      if (!connection_) connect();
    } catch (const RedisRefusal&) {
      throw;
    } catch (const RedisError& e) {
      last_failure = e.what();
    }
    if (connection_)
      if (auto reply = try_command(args)) return std::move(*reply);
    if (Clock::now() + backoff > deadline)
      throw RedisError(fmt::format("redis {} unreachable for {} s: {}", address_.url(),
                                   std::chrono::duration_cast<std::chrono::seconds>(retry_for_).count(),
                                   last_failure));
    std::this_thread::sleep_for(backoff);
    backoff = std::min<std::chrono::milliseconds>(2 * backoff, kMaxBackoff);
  }
}

void RedisClient::set(std::string_view key, std::string_view value, std::optional<int> expire_s) {
  if (expire_s)
    command({"SET", key, value, "EX", std::to_string(*expire_s)});
  else
    command({"SET", key, value});
}

void RedisClient::set_if_absent(std::string_view key, std::string_view value) {
  command({"SET", key, value, "NX"});
}

void RedisClient::expire(std::string_view key, int seconds) {
  command({"EXPIRE", key, std::to_string(seconds)});
}

std::optional<std::string> RedisClient::get(std::string_view key) {
  auto r = command({"GET", key});
  return r.nil() ? std::nullopt : std::optional(std::move(r.text));
}

bool RedisClient::exists(std::string_view key) {
  return command({"EXISTS", key}).integer > 0;
}

void RedisClient::del(const std::vector<std::string_view>& keys) {
  std::vector<std::string_view> args{"DEL"};
  args.insert(args.end(), keys.begin(), keys.end());
  command(args);
}

void RedisClient::hset(std::string_view key, std::string_view field, std::string_view value) {
  command({"HSET", key, field, value});
}

std::optional<std::string> RedisClient::hget(std::string_view key, std::string_view field) {
  auto r = command({"HGET", key, field});
  return r.nil() ? std::nullopt : std::optional(std::move(r.text));
}

void RedisClient::hdel(std::string_view key, std::string_view field) {
  command({"HDEL", key, field});
}

void RedisClient::sadd(std::string_view key, std::string_view member) {
  command({"SADD", key, member});
}

void RedisClient::srem(std::string_view key, std::string_view member) {
  command({"SREM", key, member});
}

std::vector<std::string> RedisClient::smembers(std::string_view key) {
  std::vector<std::string> out;
  for (auto& e : command({"SMEMBERS", key}).elements) out.push_back(std::move(e.text));
  return out;
}

std::string RedisClient::xadd(std::string_view key,
                              const std::vector<std::pair<std::string, std::string>>& fields) {
  std::vector<std::string_view> args{"XADD", key, "*"};
  for (const auto& [name, value] : fields) {
    args.push_back(name);
    args.push_back(value);
  }
  return command(args).text;
}

void RedisClient::xgroup_create(std::string_view key, std::string_view group, std::string_view start) {
  try {
    command({"XGROUP", "CREATE", key, group, start, "MKSTREAM"});
  } catch (const RedisError& e) {
    if (std::string_view(e.what()).find("BUSYGROUP") == std::string_view::npos) throw;
  }
}

// Each page starts after the last entry of the one before ("(ID": Redis 6.2, as XAUTOCLAIM).
std::vector<StreamEntry> RedisClient::xrange(std::string_view key) {
  const std::string count = std::to_string(kRangePage);
  std::vector<StreamEntry> out;
  std::string start = "-";
  for (;;) {
    const RedisReply reply = command({"XRANGE", key, start, "+", "COUNT", count});
    auto page = range_entries(std::string(key), reply);
    if (page.empty()) return out;
    start = "(" + page.back().id;
    out.insert(out.end(), std::make_move_iterator(page.begin()), std::make_move_iterator(page.end()));
    if (reply.elements.size() < kRangePage) return out;
  }
}

std::vector<std::string> RedisClient::xpending(std::string_view key, std::string_view group, int64_t count) {
  return pending_ids(command({"XPENDING", key, group, "-", "+", std::to_string(count)}));
}

std::vector<PendingItem> RedisClient::xpending_idle(std::string_view key, std::string_view group,
                                                    std::chrono::milliseconds min_idle, int64_t count) {
  return pending_items(
      command({"XPENDING", key, group, "IDLE", ms(min_idle), "-", "+", std::to_string(count)}));
}

std::vector<StreamEntry> RedisClient::xclaim(std::string_view key, std::string_view group,
                                             std::string_view consumer, std::chrono::milliseconds min_idle,
                                             std::string_view id) {
  return range_entries(std::string(key), command({"XCLAIM", key, group, consumer, ms(min_idle), id}));
}

std::optional<std::string> RedisClient::xgroup_last_delivered(std::string_view key, std::string_view group) {
  if (!exists(key)) return std::nullopt;
  return group_field(command({"XINFO", "GROUPS", key}), std::string(group), "last-delivered-id");
}

std::vector<StreamEntry> RedisClient::xreadgroup(std::string_view group, std::string_view consumer,
                                                 const std::vector<std::string>& keys,
                                                 std::chrono::milliseconds block) {
  const std::string block_ms = ms(block);
  std::vector<std::string_view> args{"XREADGROUP", "GROUP", group,    consumer, "COUNT",
                                     "1",          "BLOCK", block_ms, "STREAMS"};
  args.insert(args.end(), keys.begin(), keys.end());
  for (size_t i = 0; i < keys.size(); ++i) args.push_back(">");
  return stream_entries(command(args));
}

std::vector<StreamEntry> RedisClient::xread(std::string_view key, std::string_view after,
                                            std::chrono::milliseconds block) {
  if (block.count() <= 0) return stream_entries(command({"XREAD", "STREAMS", key, after}));
  return stream_entries(command({"XREAD", "BLOCK", ms(block), "STREAMS", key, after}));
}

void RedisClient::xack(std::string_view key, std::string_view group, std::string_view id) {
  command({"XACK", key, group, id});
}

std::vector<StreamEntry> RedisClient::xautoclaim(std::string_view key, std::string_view group,
                                                 std::string_view consumer,
                                                 std::chrono::milliseconds min_idle) {
  return claimed_entries(std::string(key),
                         command({"XAUTOCLAIM", key, group, consumer, ms(min_idle), "0-0", "COUNT", "1"}));
}

}  // namespace lp::server

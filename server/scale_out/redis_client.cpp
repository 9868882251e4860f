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

timeval to_timeval(std::chrono::milliseconds d) {
  return {static_cast<time_t>(d.count() / 1000), static_cast<suseconds_t>(d.count() % 1000 * 1000)};
}

RedisReply copy(const redisReply& r) {
  RedisReply out;
  switch (r.type) {
    case REDIS_REPLY_INTEGER:
      out.type = RedisReply::Type::Integer;
      out.integer = r.integer;
      break;
    case REDIS_REPLY_STRING:
    case REDIS_REPLY_STATUS:
      out.type = r.type == REDIS_REPLY_STRING ? RedisReply::Type::String : RedisReply::Type::Status;
      out.text.assign(r.str, r.len);
      break;
    case REDIS_REPLY_ARRAY:
      out.type = RedisReply::Type::Array;
      for (size_t i = 0; i < r.elements; ++i) out.elements.push_back(copy(*r.element[i]));
      break;
    default:
      break;
  }
  return out;
}

// hiredis's createArray, which every reader starts with (its static defaultFunctions).
void* (*hiredis_create_array)(const redisReadTask*, int) = nullptr;

// An array over the bound is not allocated: its count goes where the reader's privdata points (if
// anywhere), and the reader fails ("Out of memory", for any null object).
void* create_bounded_array(const redisReadTask* task, int elements) {
  if (elements <= kMaxRedisArrayElements) return hiredis_create_array(task, elements);
  if (task->privdata) *static_cast<int*>(task->privdata) = elements;
  return nullptr;
}

// Makes `reader` refuse arrays over kMaxRedisArrayElements, writing a refused count to *refused.
void bound_arrays(redisReader& reader, int* refused) {
  static redisReplyObjectFunctions functions = [&] {
    hiredis_create_array = reader.fn->createArray;
    redisReplyObjectFunctions f = *reader.fn;
    f.createArray = create_bounded_array;
    return f;
  }();
  reader.fn = &functions;
  reader.privdata = refused;
}

std::string ms(std::chrono::milliseconds d) {
  return std::to_string(d.count());
}

}  // namespace

std::optional<RedisReply> parse_reply(std::string_view wire) {
  const std::unique_ptr<redisReader, void (*)(redisReader*)> reader(redisReaderCreate(), redisReaderFree);
  if (!reader) return std::nullopt;
  bound_arrays(*reader, nullptr);
  if (redisReaderFeed(reader.get(), wire.data(), wire.size()) != REDIS_OK) return std::nullopt;
  void* raw = nullptr;
  if (redisReaderGetReply(reader.get(), &raw) != REDIS_OK || !raw) return std::nullopt;
  const std::unique_ptr<redisReply, void (*)(void*)> reply(static_cast<redisReply*>(raw), freeReplyObject);
  return copy(*reply);
}

RedisClient::RedisClient(RedisAddress address, std::chrono::milliseconds retry_for)
    : address_(std::move(address)), retry_for_(retry_for), context_(nullptr, redisFree) {}

RedisClient::~RedisClient() = default;

void RedisClient::connect() {
  context_.reset(redisConnectWithTimeout(address_.host.c_str(), address_.port, to_timeval(kConnectTimeout)));
  if (!context_) throw RedisError("cannot allocate a Redis connection");
  if (context_->err) {
    const std::string why = context_->errstr;
    context_.reset();
    throw RedisError(fmt::format("cannot connect to {}: {}", address_.url(), why));
  }
  redisSetTimeout(context_.get(), to_timeval(kCommandTimeout));
  redisEnableKeepAlive(context_.get());
  bound_arrays(*context_->reader, &refused_elements_);
}

// The reply on the open connection, nullopt when the connection failed (then dropped); throws
// RedisError for an error reply other than LOADING (Redis reading its append-only file after a restart:
// try again), and for an array over the bound (the connection dropped).
std::optional<RedisReply> RedisClient::try_command(const std::vector<std::string_view>& args) {
  const std::string_view name = args.empty() ? "" : args[0];
  std::vector<const char*> argv;
  std::vector<size_t> lengths;
  for (const auto a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  refused_elements_ = 0;
  auto* raw = static_cast<redisReply*>(
      redisCommandArgv(context_.get(), int(argv.size()), argv.data(), lengths.data()));
  if (!raw && refused_elements_ > 0) {
    context_.reset();  // the rest of the reply is unread
    const std::string what =
        fmt::format("redis {}: {} answered an array of {} elements, over the bound of {}; connection dropped",
                    name, address_.url(), refused_elements_, kMaxRedisArrayElements);
    spdlog::warn("{}", what);
    throw RedisError(what);
  }
  if (!raw) {
    spdlog::debug("redis {}: {}", address_.url(), context_->errstr);
    context_.reset();
    return std::nullopt;
  }
  const std::unique_ptr<redisReply, void (*)(void*)> reply(raw, freeReplyObject);
  if (reply->type == REDIS_REPLY_ERROR) {
    const std::string message(reply->str, reply->len);
    if (message.starts_with("LOADING")) return std::nullopt;
    throw RedisError(fmt::format("redis {}: {}", name, message));
  }
  return copy(*reply);
}

RedisReply RedisClient::command(const std::vector<std::string_view>& args) {
  std::lock_guard lock(mutex_);
  const auto deadline = Clock::now() + retry_for_;
  auto backoff = std::chrono::milliseconds(kFirstBackoff);
  std::string last_failure = "no answer";
  for (;;) {
    try {
      if (!context_) connect();
    } catch (const RedisError& e) {
      last_failure = e.what();
    }
    if (context_)
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

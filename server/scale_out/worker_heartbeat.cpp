#include "server/scale_out/worker_heartbeat.hpp"

#include <spdlog/spdlog.h>

#include <condition_variable>
#include <map>
#include <mutex>

#include "server/scale_out/redis_keys.hpp"

namespace lp::server {
namespace {

// Items of one stream looked at per call: a worker holds one at a time, so this is many workers' worth.
constexpr int64_t kPendingPage = 256;

}  // namespace

WorkerHeartbeat::WorkerHeartbeat(const RedisAddress& redis, std::string consumer)
    : redis_(redis, kHeartbeatLifetime), key_(render_keys::heartbeat(consumer)) {
  try {
    beat();
  } catch (const RedisError& e) {
    spdlog::warn("worker heartbeat: {}", e.what());
  }
  thread_ = std::jthread([this](std::stop_token stop) {
    std::mutex mutex;
    std::condition_variable_any wake;
    std::unique_lock lock(mutex);
    for (;;) {
      wake.wait_for(lock, stop, kHeartbeatEvery, [] { return false; });
      if (stop.stop_requested()) return;
      try {
        beat();
      } catch (const RedisError& e) {
        spdlog::warn("worker heartbeat: {}", e.what());
      }
    }
  });
}

WorkerHeartbeat::~WorkerHeartbeat() {
  thread_.request_stop();
  thread_.join();
  try {
    redis_.del({key_});
  } catch (const RedisError&) {
  }
}

void WorkerHeartbeat::beat() {
  redis_.command({"SET", key_, "1", "PX", std::to_string(kHeartbeatLifetime.count())});
}

int64_t live_workers(RedisClient& redis) {
  const std::string pattern = render_keys::heartbeat("*");
  int64_t workers = 0;
  std::string cursor = "0";
  do {  // SCAN, not KEYS: a Redis with many keys is not held up
    const RedisReply page = redis.command({"SCAN", cursor, "MATCH", pattern, "COUNT", "1000"});
    if (page.type != RedisReply::Type::Array || page.elements.size() != 2) break;
    cursor = page.elements[0].text;
    workers += int64_t(page.elements[1].elements.size());
  } while (cursor != "0");
  return workers;
}

std::vector<std::string> orphaned_items(RedisClient& redis, const std::string& stream,
                                        const std::string& group) {
  std::map<std::string, bool> alive;
  std::vector<std::string> out;
  for (const PendingItem& item : redis.xpending_idle(stream, group, kHeartbeatLifetime, kPendingPage)) {
    auto [it, added] = alive.try_emplace(item.consumer, false);
    if (added) it->second = redis.exists(render_keys::heartbeat(item.consumer));
    if (!it->second) out.push_back(item.id);
  }
  return out;
}

}  // namespace lp::server

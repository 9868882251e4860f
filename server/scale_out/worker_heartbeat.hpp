#pragma once
// A worker's heartbeat: while it lives, a thread sets its key (redis_keys.hpp) every kHeartbeatEvery to
// expire after kHeartbeatLifetime, so the items a dead worker held go to others within seconds
// (orphaned_items) rather than after --redis-claim-timeout-s. A worker that stops deletes its key.
#include <chrono>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "server/scale_out/redis_client.hpp"

namespace lp::server {

inline constexpr std::chrono::milliseconds kHeartbeatEvery{1000};
inline constexpr std::chrono::milliseconds kHeartbeatLifetime{3000};

class WorkerHeartbeat {
 public:
  // Sets the key before it returns (a warning if Redis cannot be reached), then keeps it set.
  WorkerHeartbeat(const RedisAddress& redis, std::string consumer);
  ~WorkerHeartbeat();
  WorkerHeartbeat(const WorkerHeartbeat&) = delete;
  WorkerHeartbeat& operator=(const WorkerHeartbeat&) = delete;

 private:
  void beat();
  RedisClient redis_;
  const std::string key_;
  std::jthread thread_;
};

// The workers with a live heartbeat on this Redis.
int64_t live_workers(RedisClient& redis);

// The items of the stream's group held for kHeartbeatLifetime or more by consumers without a heartbeat:
// the items of workers that died.
std::vector<std::string> orphaned_items(RedisClient& redis, const std::string& stream,
                                        const std::string& group);

}  // namespace lp::server

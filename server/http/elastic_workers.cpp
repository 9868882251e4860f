#include "server/http/elastic_workers.hpp"

#include <spdlog/spdlog.h>

#include <system_error>

namespace lp::server {
namespace {

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ElasticWorkers::ElasticWorkers(int base, std::chrono::milliseconds patience, Wait wait, Serve serve)
    : base_(std::max(base, 1)), patience_(patience), wait_(std::move(wait)), serve_(std::move(serve)) {
  std::lock_guard lock(mutex_);
  for (int i = 0; i < base_; ++i) start_worker();
  watcher_ = std::thread([this] { watch(); });
}

ElasticWorkers::~ElasticWorkers() {
  {
    std::unique_lock lock(mutex_);
    ending_ = true;
    saturated_.notify_all();
    changed_.notify_all();
    changed_.wait(lock, [this] { return workers_.empty(); });
  }
  watcher_.join();
}

int ElasticWorkers::threads() const {
  std::lock_guard lock(mutex_);
  return int(workers_.size());
}

// Called with the mutex held.
void ElasticWorkers::start_worker() {
  Worker& worker = workers_.emplace_back();
  try {
    std::thread([this, &worker] { work(worker); }).detach();
  } catch (const std::system_error& e) {
    spdlog::error("no thread for another HTTP worker ({} running): {}", workers_.size() - 1, e.what());
    workers_.pop_back();
  }
}

void ElasticWorkers::work(Worker& self) {
  while (join_waiting()) {
    const std::optional<uint64_t> task = wait_();
    if (--waiting_ == 0 && task && watcher_idle_) {
      std::lock_guard lock(mutex_);  // under the lock, so the watcher cannot miss the notification
      saturated_.notify_one();
    }
    if (!task) break;
    self.busy_since = now_ns();
    serve_(*task);
    self.busy_since = 0;
  }
  std::lock_guard lock(mutex_);
  workers_.remove_if([&](const Worker& w) { return &w == &self; });
  changed_.notify_all();
}

// Counts the calling thread among those waiting for work, unless `base` already are: then the thread
// was added while the others were busy, and is no longer needed.
bool ElasticWorkers::join_waiting() {
  int waiting = waiting_;
  do {
    if (waiting >= base_) return false;
  } while (!waiting_.compare_exchange_weak(waiting, waiting + 1));
  return true;
}

// Adds a thread whenever every thread has been busy with one task for longer than the patience. While
// some thread waits for work the watcher sleeps, and it is woken only from that sleep (not on each task
// taken under load, which would cost a context switch per request).
void ElasticWorkers::watch() {
  std::unique_lock lock(mutex_);
  while (!ending_) {
    watcher_idle_ = true;
    saturated_.wait(lock, [this] { return ending_ || waiting_ == 0; });
    watcher_idle_ = false;
    changed_.wait_for(lock, patience_, [this] { return ending_; });
    if (!ending_ && waiting_ == 0 && all_stuck()) start_worker();
  }
}

bool ElasticWorkers::all_stuck() const {
  const int64_t limit = now_ns() - std::chrono::nanoseconds(patience_).count();
  for (const Worker& w : workers_) {
    const int64_t since = w.busy_since;
    if (since == 0 || since > limit) return false;
  }
  return true;
}

}  // namespace lp::server

#pragma once
// A pool of threads that serve tasks one at a time, sized to the cores while the tasks are short and
// grown while they are not. `base` threads wait for work; when every thread has been on its current task
// for longer than `patience` (a request blocked on a slow client, an event stream, a long computation),
// another thread is started, so a short request is never queued behind long ones for more than about
// `patience`. A thread that finishes its task while `base` others are waiting ends. Few threads run at
// once under load, so requests are taken in arrival order and the cores are not shared by dozens of
// runnable threads (which is what makes the tail latency of thread-per-connection servers long).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <list>
#include <mutex>
#include <optional>
#include <thread>

namespace lp::server {

class ElasticWorkers {
 public:
  // Blocks until a task is ready; std::nullopt ends the calling thread.
  using Wait = std::function<std::optional<uint64_t>()>;
  using Serve = std::function<void(uint64_t)>;

  ElasticWorkers(int base, std::chrono::milliseconds patience, Wait wait, Serve serve);
  // Waits for every thread to end: the caller makes `wait` return std::nullopt first.
  ~ElasticWorkers();
  ElasticWorkers(const ElasticWorkers&) = delete;
  ElasticWorkers& operator=(const ElasticWorkers&) = delete;

  int threads() const;

 private:
  struct Worker {
    std::atomic<int64_t> busy_since{0};  // steady-clock nanoseconds; 0 while waiting for a task
  };
  void start_worker();
  void work(Worker& self);
  bool join_waiting();
  void watch();
  bool all_stuck() const;

  const int base_;
  const std::chrono::milliseconds patience_;
  const Wait wait_;
  const Serve serve_;
  std::atomic<int> waiting_{0};
  mutable std::mutex mutex_;
  std::condition_variable saturated_;  // the watcher waits here until no thread waits for work
  std::condition_variable changed_;    // a thread ended, or the pool is ending
  std::atomic<bool> watcher_idle_{false};
  std::list<Worker> workers_;
  bool ending_ = false;
  std::thread watcher_;
};

}  // namespace lp::server

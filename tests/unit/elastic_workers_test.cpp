// The HTTP worker pool grows while every worker is held by a long task, so a short task is never queued
// behind long ones, and shrinks back to its base size once the long tasks end.
#include "server/http/elastic_workers.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

namespace lp::server {
namespace {

using namespace std::chrono_literals;

// Tasks handed to the workers in order; task 0 ends a worker.
class TaskQueue {
 public:
  void push(uint64_t task) {
    std::lock_guard lock(mutex_);
    tasks_.push_back(task);
    ready_.notify_one();
  }
  std::optional<uint64_t> pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [this] { return !tasks_.empty() || ended_; });
    if (tasks_.empty()) return std::nullopt;
    const uint64_t task = tasks_.front();
    tasks_.pop_front();
    return task;
  }
  void end() {
    std::lock_guard lock(mutex_);
    ended_ = true;
    ready_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<uint64_t> tasks_;
  bool ended_ = false;
};

// Long tasks (1) block until released; a short task (2) is counted.
struct Tasks {
  std::mutex mutex;
  std::condition_variable changed;
  bool released = false;
  int long_running = 0;
  int short_done = 0;

  void run(uint64_t task) {
    std::unique_lock lock(mutex);
    if (task == 2) {
      ++short_done;
    } else {
      ++long_running;
      changed.notify_all();
      changed.wait(lock, [this] { return released; });
      --long_running;
    }
    changed.notify_all();
  }
  template <class Predicate>
  bool wait_until(Predicate done) {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, 10s, [&] { return done(*this); });
  }
};

TEST(ElasticWorkers, GrowsPastLongTasksAndShrinksBack) {
  TaskQueue queue;
  Tasks tasks;
  {
    ElasticWorkers pool(
        2, 5ms, [&] { return queue.pop(); }, [&](uint64_t t) { tasks.run(t); });
    EXPECT_EQ(pool.threads(), 2);
    for (int i = 0; i < 6; ++i) queue.push(1);  // six long tasks: three times the base size
    queue.push(2);                              // and a short one behind them
    EXPECT_TRUE(tasks.wait_until([](const Tasks& t) { return t.long_running == 6 && t.short_done == 1; }))
        << "the pool did not grow past its blocked workers";
    EXPECT_GE(pool.threads(), 7);
    {
      std::lock_guard lock(tasks.mutex);
      tasks.released = true;
    }
    tasks.changed.notify_all();
    EXPECT_TRUE(tasks.wait_until([](const Tasks& t) { return t.long_running == 0; }));
    for (int i = 0; i < 1000 && pool.threads() > 2; ++i) std::this_thread::sleep_for(5ms);
    EXPECT_EQ(pool.threads(), 2) << "threads added for the long tasks did not end";
    queue.end();
  }
}

}  // namespace
}  // namespace lp::server

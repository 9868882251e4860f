#pragma once
// Where render work runs: a oneTBB arena of low priority (oneTBB gives its threads to interactive
// requests, which run in normal-priority arenas, first) whose threads step back to --render-priority
// (thread_priority.hpp). Local render jobs and the work items of a render split over Redis both
// run in one.
//
// Fair shares: the caller does not join the arena, it hands the work over and waits, and the process has
// enough oneTBB workers for every arena it may have working at once to get all of its threads
// (worker_threads). Each running job then has the same number of threads and the OS shares the cores
// evenly between them. A caller that joined would add a thread of its own to its job: of two renders on
// two cores with one worker, one had two threads and the other one, and a third got none.
#include <oneapi/tbb/task_arena.h>

#include <cstddef>
#include <exception>
#include <future>
#include <optional>

#include "server/jobs/thread_priority.hpp"

namespace lp::server {

class JobArena {
 public:
  // `concurrency` threads, all cores when 0 or less.
  JobArena(int concurrency, RenderPriority priority);
  JobArena(const JobArena&) = delete;
  JobArena& operator=(const JobArena&) = delete;

  // Runs `f` on the arena's workers and waits for it; an exception it throws is rethrown here.
  template <class F>
  void execute(F&& f) {
    std::promise<void> done;
    arena_.enqueue([&] {
      try {
        f();
        done.set_value();
      } catch (...) {
        done.set_exception(std::current_exception());
      }
    });
    done.get_future().get();
  }

  // The oneTBB worker threads a process needs for `arenas` arenas of `threads` threads (0: one per
  // core) each to run at once.
  static std::size_t worker_threads(int threads, int arenas);

 private:
  tbb::task_arena arena_;
  std::optional<RenderThreadPriority> lowered_;
};

}  // namespace lp::server

#pragma once
// Where render work runs: a oneTBB arena of low priority (oneTBB gives its threads to interactive
// requests, which run in normal-priority arenas, first) whose threads, and the thread that creates it,
// step back to --render-priority (render_thread_priority.hpp). Local render jobs and the work items of a
// render split over Redis both run in one.
#include <oneapi/tbb/task_arena.h>

#include <optional>

#include "server/render_thread_priority.hpp"

namespace lp::server {

class RenderArena {
 public:
  // `concurrency` threads, all cores when 0 or less. Lowers the calling thread too.
  RenderArena(int concurrency, RenderPriority priority);
  RenderArena(const RenderArena&) = delete;
  RenderArena& operator=(const RenderArena&) = delete;

  template <class F>
  void execute(F&& f) {
    arena_.execute(std::forward<F>(f));
  }

 private:
  tbb::task_arena arena_;
  std::optional<RenderThreadPriority> lowered_;
};

}  // namespace lp::server

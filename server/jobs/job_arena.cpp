#include "server/jobs/job_arena.hpp"

#include <oneapi/tbb/info.h>

#include <algorithm>

namespace lp::server {

JobArena::JobArena(int concurrency, RenderPriority priority)
    : arena_(concurrency > 0 ? concurrency : tbb::info::default_concurrency(), 0,
             tbb::task_arena::priority::low) {
  arena_.initialize();
  lowered_.emplace(arena_, priority);
}

std::size_t JobArena::worker_threads(int threads, int arenas) {
  return std::size_t(threads > 0 ? threads : tbb::info::default_concurrency()) *
         std::size_t(std::max(1, arenas));
}

}  // namespace lp::server

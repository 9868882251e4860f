#include "server/render_arena.hpp"

#include <oneapi/tbb/info.h>

namespace lp::server {

RenderArena::RenderArena(int concurrency, RenderPriority priority)
    : arena_(concurrency > 0 ? concurrency : tbb::info::default_concurrency(), 1,
             tbb::task_arena::priority::low) {
  arena_.initialize();
  lowered_.emplace(arena_, priority);
  lower_to_render_priority(priority);
}

}  // namespace lp::server

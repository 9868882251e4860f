#include "server/render_thread_priority.hpp"

#include <pthread.h>
#include <sched.h>
#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>

namespace lp::server {
void lower_to_render_priority() {
  thread_local bool lowered = false;
  if (lowered) return;
  lowered = true;
  const sched_param param{};
  if (const int error = pthread_setschedparam(pthread_self(), SCHED_IDLE, &param))
    spdlog::debug("render thread priority unchanged: {}", std::strerror(error));
}

RenderThreadPriority::RenderThreadPriority(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
  observe(true);
}

RenderThreadPriority::~RenderThreadPriority() {
  observe(false);
}

void RenderThreadPriority::on_scheduler_entry(bool) {
  lower_to_render_priority();
}

}  // namespace lp::server

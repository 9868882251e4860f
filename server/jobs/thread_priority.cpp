#include "server/jobs/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace lp::server {
namespace {

// Linux applies a nice value given for a thread id to that thread alone. The step is taken from the
// nice value the server was started with, so a server started under `nice` keeps its renders below it.
int lower_nice(int step) {
  const auto thread = static_cast<id_t>(gettid());
  errno = 0;
  const int inherited = getpriority(PRIO_PROCESS, thread);
  if (errno != 0) return errno;
  return setpriority(PRIO_PROCESS, thread, std::min(inherited + step, kWeakestNice)) == 0 ? 0 : errno;
}

int idle_policy() {
  const sched_param param{};
  return pthread_setschedparam(pthread_self(), SCHED_IDLE, &param);
}

}  // namespace

void lower_to_render_priority(RenderPriority priority) {
  thread_local bool lowered = false;
  if (lowered || priority == RenderPriority::Normal) return;
  lowered = true;
  if (const int error = priority == RenderPriority::Idle ? idle_policy() : lower_nice(kLowRenderNiceStep))
    spdlog::debug("render thread priority unchanged: {}", std::strerror(error));
}

RenderThreadPriority::RenderThreadPriority(tbb::task_arena& arena, RenderPriority priority)
    : tbb::task_scheduler_observer(arena), priority_(priority) {
  observe(true);
}

RenderThreadPriority::~RenderThreadPriority() {
  observe(false);
}

void RenderThreadPriority::on_scheduler_entry(bool) {
  lower_to_render_priority(priority_);
}

}  // namespace lp::server

#include "server/render_thread_priority.hpp"

#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace lp::server {
namespace {

constexpr int kRenderNice = 10;  // about a tenth of a normal thread's CPU share when both want a core

}  // namespace

void lower_to_render_priority() {
  thread_local bool lowered = false;
  if (lowered) return;
  lowered = true;
  if (setpriority(PRIO_PROCESS, id_t(gettid()), kRenderNice) != 0)
    spdlog::debug("render thread priority unchanged: {}", std::strerror(errno));
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

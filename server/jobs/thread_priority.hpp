#pragma once
// Render threads yield the CPU to the threads answering requests. A render keeps every core busy for
// minutes; a request needs a core for microseconds at a time. At equal OS priority the scheduler shares
// the cores fairly, and a request's thread, woken while a render thread runs, may wait for that thread's
// time slice to end (milliseconds). --render-priority chooses how far render threads step back:
//   low (default)  nice +10: a woken request thread takes the core at once (its weight is about ten
//                  times a render thread's), and renders still get about a tenth of a core that other
//                  programs keep busy, so they always finish.
//   idle           SCHED_IDLE: renders run only on cores nothing else wants. They never delay another
//                  program, but they stall for as long as anything else keeps the cores busy, and so can
//                  a request's parallel loop that a lowered oneTBB worker joined.
//   normal         renders share the cores equally with everything else.
// Each oneTBB worker that joins a render arena is lowered the first time it renders; an unprivileged thread
// cannot raise itself again, so such a worker stays lowered when it later helps a request's parallel loop
// (bulk work: large sample sets, decodes; the request's own thread keeps its priority).
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_scheduler_observer.h>

#include "engine/core/enum_table.hpp"

namespace lp::server {

enum class RenderPriority { Low, Idle, Normal };

constexpr auto enum_entries(RenderPriority) {
  return std::to_array<EnumEntry<RenderPriority>>(
      {{RenderPriority::Low, "low"}, {RenderPriority::Idle, "idle"}, {RenderPriority::Normal, "normal"}});
}

// How far RenderPriority::Low lowers render threads below the server's own nice value, which Linux
// caps at kWeakestNice.
inline constexpr int kLowRenderNiceStep = 10;
inline constexpr int kWeakestNice = 19;

// Lowers the calling thread to `priority`, once per thread.
void lower_to_render_priority(RenderPriority priority);

// Lowers each thread that enters `arena` while this object lives.
class RenderThreadPriority final : public tbb::task_scheduler_observer {
 public:
  RenderThreadPriority(tbb::task_arena& arena, RenderPriority priority);
  ~RenderThreadPriority() override;
  void on_scheduler_entry(bool worker) override;

 private:
  RenderPriority priority_;
};

}  // namespace lp::server

#pragma once
// Render threads yield the CPU to the threads answering requests. A render keeps every core busy for
// minutes; a request needs a core for microseconds at a time. At equal OS priority the scheduler shares
// the cores fairly, and a request's thread, woken while a render thread runs, may wait for that thread's
// time slice to end (milliseconds); even at a lower nice value it is not always run at once. Render
// threads are therefore SCHED_IDLE: they run whenever a core has nothing else to do, and a woken request
// thread always takes the core from them at once. The runner thread of a job and each oneTBB worker that
// joins a render arena are lowered the first time they render. A worker stays lowered when it later helps
// a request's parallel loop: such loops are bulk work (large sample sets, decodes), and the request's own
// thread keeps its priority.
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_scheduler_observer.h>

namespace lp::server {

// Lowers the calling thread's priority to the render level, once per thread.
void lower_to_render_priority();

// Lowers each thread that enters `arena` while this object lives.
class RenderThreadPriority final : public tbb::task_scheduler_observer {
 public:
  explicit RenderThreadPriority(tbb::task_arena& arena);
  ~RenderThreadPriority() override;
  void on_scheduler_entry(bool worker) override;
};

}  // namespace lp::server

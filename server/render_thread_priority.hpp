#pragma once
// Render threads yield the CPU to connection threads. A render keeps every core busy for minutes; the
// threads answering requests wake for microseconds at a time. At equal OS priority the scheduler shares
// the cores fairly between them, and a small request waits behind render time slices; at a lower nice
// value for the render threads it runs at once. The runner thread of a job and each oneTBB worker that
// joins a render arena are lowered the first time they render. An unprivileged process cannot raise a
// thread's priority again, so a worker stays lowered when it later helps a request's parallel loop:
// such loops are bulk work (large sample sets, decodes), and the request's own thread keeps its priority.
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

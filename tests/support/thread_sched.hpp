#pragma once
// The kernel's view of a process's threads (/proc/PID/task/TID/stat): each thread's nice value and
// scheduling policy, to see from outside which threads --render-priority lowered.
#include <vector>

namespace lp::test {

struct ThreadSched {
  int nice;
  int policy;
  bool operator==(const ThreadSched&) const = default;
};

struct ProcessThreads {
  ThreadSched main;
  std::vector<ThreadSched> all;  // the main thread among them
};

ProcessThreads threads_of(int pid);

// That the process's threads are at `render` or at the main thread's scheduling, no other, and at least
// `renderers` at `render` (gtest expectations).
void expect_render_threads_at(const ProcessThreads& threads, ThreadSched render, int renderers);

}  // namespace lp::test

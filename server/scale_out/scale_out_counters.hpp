#pragma once
// What this server did with the work items of split renders, for GET /metrics: as the server a render
// was submitted to (items published, merged, waiting), and as a worker (items rendered, and taken over
// from workers that died or stalled). Thread-safe.
#include <atomic>
#include <cstdint>

namespace lp::server {

struct ScaleOutCounters {
  std::atomic<uint64_t> published{0};   // items this server's renders put on Redis (again after a loss too)
  std::atomic<uint64_t> merged{0};      // items whose partial film this server merged
  std::atomic<int64_t> outstanding{0};  // items of this server's running renders not yet merged
  std::atomic<uint64_t> rendered{0};    // items this worker rendered and uploaded
  std::atomic<uint64_t> taken_over{0};  // items this worker took from another that died or stalled
};

}  // namespace lp::server

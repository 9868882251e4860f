#pragma once
// What renders have traced since the server started, for GET /metrics: counters that only grow, added to
// at the end of every pass (rate() over them gives samples and rays per second). Thread-safe.
#include <atomic>
#include <cstdint>

namespace lp::server {

struct RenderCounters {
  std::atomic<uint64_t> samples{0};  // camera samples
  std::atomic<uint64_t> rays{0};     // all rays: camera, bounce, shadow
  std::atomic<double> seconds{0};    // time spent in passes, summed over the renders running at once

  void add(uint64_t pass_samples, uint64_t pass_rays, double pass_seconds) {
    samples.fetch_add(pass_samples, std::memory_order_relaxed);
    rays.fetch_add(pass_rays, std::memory_order_relaxed);
    seconds.fetch_add(pass_seconds, std::memory_order_relaxed);
  }
};

}  // namespace lp::server

#include "server/shutdown.hpp"

#include <spdlog/spdlog.h>

#include <thread>

namespace lp::server {

void shut_down(App& app, Server& server) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  server.stop_accepting();
  app.prefilters.shutdown(std::chrono::seconds(app.options.shutdown_grace_s));  // they stop at their next row
  app.turntables.shutdown(std::chrono::seconds(app.options.shutdown_grace_s));  // at their next frame
  app.renders.shutdown(std::chrono::seconds(app.options.shutdown_grace_s));
  const auto streams_deadline = Clock::now() + kStreamDrain;
  while (app.event_streams.load() > 0 && Clock::now() < streams_deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (const int open = app.event_streams.load())
    spdlog::warn("shutting down: {} event stream(s) did not close", open);
  server.close_connections();
  spdlog::info("shutdown: renders stopped and state written in {:.2f} s",
               std::chrono::duration<double>(Clock::now() - start).count());
}

}  // namespace lp::server

#pragma once
// The server's log: spdlog's asynchronous logger in front of the coloured stdout sink. Request threads
// format their line and queue it; one background thread writes and flushes. Written synchronously, the
// access line of every request made all connection threads queue for one write and flush of stdout, the
// largest source of tail latency for small requests under load.
#include <spdlog/common.h>

namespace lp::server {

class Logging {
 public:
  explicit Logging(spdlog::level::level_enum level);
  ~Logging();  // writes every queued line
  Logging(const Logging&) = delete;
  Logging& operator=(const Logging&) = delete;
};

}  // namespace lp::server

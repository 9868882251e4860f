#pragma once
// The server's log: spdlog's asynchronous loggers in front of stdout. Request threads format their line
// and queue it; one background thread writes and flushes. Written synchronously, the access line of every
// request made all connection threads queue for one write and flush of stdout, the largest source of
// tail latency for small requests under load. Access lines have a logger of their own, "access", so that
// in JSON they can carry the request's fields (json_log_formatter.hpp).
#include <spdlog/common.h>
#include <spdlog/logger.h>

#include <memory>

#include "server/observability/log_format.hpp"

namespace lp::server {

class Logging {
 public:
  Logging(spdlog::level::level_enum level, LogFormat format);
  ~Logging();  // writes every queued line
  Logging(const Logging&) = delete;
  Logging& operator=(const Logging&) = delete;
};

// The logger of access lines: "access" once Logging is set up, else the default logger.
std::shared_ptr<spdlog::logger> access_logger();

}  // namespace lp::server

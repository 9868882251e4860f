#pragma once
// spdlog lines as JSON, one object a line: {"time":"2025-01-02T03:04:05.678Z","level":"info","message":..}
// in UTC. An access line's message is already the JSON members of the line but its time and level
// (`"message":"GET / 200 0.3 ms","request_id":..`, access_log.hpp), written as they are.
#include <spdlog/formatter.h>

#include <memory>

namespace lp::server {

class JsonLogFormatter final : public spdlog::formatter {
 public:
  enum class Payload { Message, Members };
  explicit JsonLogFormatter(Payload payload) : payload_(payload) {}

  void format(const spdlog::details::log_msg& msg, spdlog::memory_buf_t& dest) override;
  std::unique_ptr<spdlog::formatter> clone() const override;

 private:
  Payload payload_;
};

}  // namespace lp::server

#include "server/observability/logging.hpp"

#include <spdlog/async.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <string>

#include "server/observability/json_log_formatter.hpp"

namespace lp::server {
namespace {

constexpr size_t kQueuedLines = 8192;  // when full, a logging thread waits: no line is dropped
constexpr const char* kAccessLogger = "access";

spdlog::sink_ptr stdout_sink(LogFormat format, JsonLogFormatter::Payload payload) {
  if (format == LogFormat::Text) {
    auto sink = std::make_shared<spdlog::sinks::stdout_color_sink_mt>();
    sink->set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");
    return sink;
  }
  auto sink = std::make_shared<spdlog::sinks::stdout_sink_mt>();  // the two share the console's mutex
  sink->set_formatter(std::make_unique<JsonLogFormatter>(payload));
  return sink;
}

std::shared_ptr<spdlog::logger> async_logger(const std::string& name, spdlog::sink_ptr sink) {
  return std::make_shared<spdlog::async_logger>(name, std::move(sink), spdlog::thread_pool(),
                                                spdlog::async_overflow_policy::block);
}

}  // namespace

Logging::Logging(spdlog::level::level_enum level, LogFormat format) {
  spdlog::init_thread_pool(kQueuedLines, 1);  // one thread: the lines of both loggers keep their order
  spdlog::set_default_logger(
      async_logger("lightprobe", stdout_sink(format, JsonLogFormatter::Payload::Message)));
  spdlog::register_logger(
      async_logger(kAccessLogger, stdout_sink(format, JsonLogFormatter::Payload::Members)));
  spdlog::set_level(level);
}

Logging::~Logging() {
  spdlog::shutdown();
}

std::shared_ptr<spdlog::logger> access_logger() {
  auto logger = spdlog::get(kAccessLogger);
  return logger ? logger : spdlog::default_logger();
}

}  // namespace lp::server

#include "server/logging.hpp"

#include <spdlog/async.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace lp::server {
namespace {

constexpr size_t kQueuedLines = 8192;  // when full, a logging thread waits: no line is dropped

}  // namespace

Logging::Logging(spdlog::level::level_enum level) {
  spdlog::init_thread_pool(kQueuedLines, 1);
  auto logger = spdlog::create_async<spdlog::sinks::stdout_color_sink_mt>("lightprobe");
  spdlog::set_default_logger(std::move(logger));
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");
  spdlog::set_level(level);
}

Logging::~Logging() {
  spdlog::shutdown();
}

}  // namespace lp::server

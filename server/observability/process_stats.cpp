#include "server/observability/process_stats.hpp"

#include <unistd.h>

#include <chrono>
#include <fstream>

namespace lp::server {
namespace {

const auto kStarted = std::chrono::system_clock::now();

}  // namespace

int64_t resident_memory_bytes() {
  std::ifstream statm("/proc/self/statm");
  int64_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * int64_t(sysconf(_SC_PAGESIZE));
}

double process_start_time_s() {
  return std::chrono::duration<double>(kStarted.time_since_epoch()).count();
}

}  // namespace lp::server

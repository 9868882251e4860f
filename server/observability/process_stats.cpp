#include "server/observability/process_stats.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <utility>

namespace lp::server {
namespace {

const auto kStarted = std::chrono::system_clock::now();

// /proc/self/statm's first two fields: the virtual and the resident size, in pages.
std::pair<int64_t, int64_t> statm_pages() {
  std::ifstream statm("/proc/self/statm");
  int64_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return {0, 0};
  return {size_pages, resident_pages};
}

double seconds(const timeval& t) {
  return double(t.tv_sec) + double(t.tv_usec) * 1e-6;
}

}  // namespace

int64_t resident_memory_bytes() {
  return statm_pages().second * int64_t(sysconf(_SC_PAGESIZE));
}

int64_t virtual_memory_bytes() {
  return statm_pages().first * int64_t(sysconf(_SC_PAGESIZE));
}

double process_cpu_seconds() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

int64_t open_file_descriptors() {
  std::error_code error;
  int64_t n = 0;
  for (std::filesystem::directory_iterator it("/proc/self/fd", error), end; !error && it != end;
       it.increment(error))
    ++n;
  return error ? -1 : n - 1;  // less the descriptor of the listing itself
}

int64_t max_file_descriptors() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return -1;
  return int64_t(limit.rlim_cur);
}

double process_start_time_s() {
  return std::chrono::duration<double>(kStarted.time_since_epoch()).count();
}

}  // namespace lp::server

#pragma once
// The process's resident memory, for the benchmarks that measure what a structure holds.
#include <cstdint>
#include <fstream>
#include <string>

namespace lp::bench {

// A field of /proc/self/status in bytes ("VmRSS", "VmHWM").
inline int64_t status_bytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string key; status >> key;) {
    int64_t kib = 0;
    if (key == field + ":" && status >> kib) return kib * 1024;
    status.ignore(1 << 20, '\n');
  }
  return 0;
}

// Sets the peak (VmHWM) to the resident memory now.
inline void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

}  // namespace lp::bench

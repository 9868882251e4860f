#pragma once
// Figures of the server's own process, for GET /metrics.
#include <cstdint>

namespace lp::server {

// Resident memory (RSS) in bytes, from /proc/self/statm; 0 if it cannot be read.
int64_t resident_memory_bytes();
// Virtual memory size in bytes, from /proc/self/statm; 0 if it cannot be read.
int64_t virtual_memory_bytes();
// When the process started (its static initialisation), in seconds since the Unix epoch.
double process_start_time_s();
// User and system CPU time the process has used, in seconds.
double process_cpu_seconds();
// File descriptors open (entries of /proc/self/fd), and the most it may open (RLIMIT_NOFILE, soft);
// -1 if unknown.
int64_t open_file_descriptors();
int64_t max_file_descriptors();

}  // namespace lp::server

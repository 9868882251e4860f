#pragma once
// Figures of the server's own process, for GET /metrics.
#include <cstdint>

namespace lp::server {

// Resident memory (RSS) in bytes, from /proc/self/statm; 0 if it cannot be read.
int64_t resident_memory_bytes();
// When the process started (its static initialisation), in seconds since the Unix epoch.
double process_start_time_s();

}  // namespace lp::server

#pragma once
// The memory this process may use: the machine's physical memory, or the cgroup's limit when lower.
#include <cstdint>

namespace lp::server {

int64_t machine_memory_bytes();

}  // namespace lp::server

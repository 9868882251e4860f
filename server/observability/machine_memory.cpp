#include "server/observability/machine_memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace lp::server {
namespace {

// The first limit found in the cgroup v2 or v1 files; 0 when none ("max", absent).
int64_t cgroup_limit_bytes() {
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    std::string value;
    if (!(in >> value) || value == "max") continue;
    try {
      return std::stoll(value);
    } catch (const std::exception&) {
    }
  }
  return 0;
}

}  // namespace

int64_t machine_memory_bytes() {
  const int64_t physical = int64_t(sysconf(_SC_PHYS_PAGES)) * int64_t(sysconf(_SC_PAGE_SIZE));
  const int64_t cgroup = cgroup_limit_bytes();
  return cgroup > 0 ? std::min(physical, cgroup) : physical;
}

}  // namespace lp::server

#pragma once
// What a worker fetches from the coordinator of a split render by content hash (GET /api/v1/content/{hash}
// at the render's source URL, with this server's --auth-token): a map or a mesh bundle. The body is
// bounded (a Content-Length over the bound is refused before the body, and the bytes are counted while
// they arrive) and its bytes are reserved in the memory budget as they arrive.
#include <cstdint>
#include <string>

#include "engine/core/memory_budget.hpp"
#include "server/app.hpp"

namespace lp::server {

struct Download {
  std::string bytes;
  MemoryReservation memory;  // for `bytes`, Transient
};

// Throws std::runtime_error naming `what` (a failed or refused fetch, a body over `max_bytes`), or
// MemoryBudgetError.
Download download_content(App& app, const std::string& source_url, const std::string& hash, int64_t max_bytes,
                          const std::string& what);

}  // namespace lp::server

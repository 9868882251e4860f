#include "server/http/memory_refusal.hpp"

#include "server/http/responses.hpp"

namespace lp::server {

void send_memory_refusal(httplib::Response& res, const MemoryBudgetError& error) {
  if (error.transient()) {
    res.set_header("Retry-After", std::to_string(kMemoryRetryAfterS));
    send_error(res, api::ErrorCode::MemoryBusy,
               std::string(error.what()) + "; retry later (--max-memory-mb)");
  } else {
    send_error(res, api::ErrorCode::InsufficientMemory,
               std::string(error.what()) +
                   "; delete maps or finished renders to make room, or start the server with a larger "
                   "--max-memory-mb");
  }
}

}  // namespace lp::server

#pragma once
// How a refusal of the memory budget (--max-memory-mb) is answered: 503 with Retry-After when work in
// flight holds the memory, 507 when the request cannot fit while the loaded maps and kept renders stay.
#include <httplib.h>

#include "engine/core/memory_budget.hpp"

namespace lp::server {

inline constexpr int kMemoryRetryAfterS = 2;

void send_memory_refusal(httplib::Response& res, const MemoryBudgetError& error);

}  // namespace lp::server

#pragma once
// Response bodies counted in the memory budget until they are written.
#include <httplib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/memory_budget.hpp"

namespace lp::server {

// Sends `bytes` as the body. `memory` (reserved for them and for the work that made them) shrinks to
// their size, and is released once the response has been written.
void send_reserved(httplib::Response& res, std::vector<uint8_t> bytes, const std::string& content_type,
                   MemoryReservation memory);

}  // namespace lp::server

#pragma once
// Response bodies counted in the memory budget until they are written.
#include <httplib.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/memory_budget.hpp"

namespace lp::server {

// Sends `bytes` as the body. `memory` (reserved for them and for the work that made them) shrinks to
// their size, and is released once the response has been written.
void send_reserved(httplib::Response& res, std::vector<uint8_t> bytes, const std::string& content_type,
                   MemoryReservation memory);

// Sends a width x height RGB8 picture as PNG. The memory of the drawing (`drawing_bytes`: the pixels and
// whatever `draw` needs) and of the PNG encoding is reserved in `budget` for `what` before `draw` runs.
void send_png_picture(httplib::Response& res, const MemoryBudget& budget, int64_t width, int64_t height,
                      int64_t drawing_bytes, std::string_view what,
                      const std::function<std::vector<uint8_t>()>& draw);

}  // namespace lp::server

#pragma once
// OpenEXR headers walked exactly as the library's C++ reader (Header::readFrom) walks them, before it
// does. That reader allocates the declared size of an unknown attribute before reading it, reads known
// types by their own layout whatever the declared size says, and keeps the last of a repeated
// attribute where the core reader keeps the first. So a header is refused unless every attribute's
// declared size fits in the file and is exactly what its type consumes, and no name repeats; then the
// core reader (used for the capacity check) and the C++ reader (used to decode) see the same header.
#include <cstdint>
#include <span>

namespace lp {

// Throws lp::Error: Corrupt for a header the two readers could read differently, Unsupported for
// attribute types whose layout we do not check.
void check_exr_attributes(std::span<const uint8_t> bytes);

}  // namespace lp

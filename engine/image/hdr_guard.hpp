#pragma once
// stb_image's Radiance decoder loops forever on some truncated files (at the end of input it reads
// run counts of 0, which never advance). Before handing bytes to it we walk the scanline structure
// ourselves and refuse anything incomplete or malformed.
#include <cstddef>
#include <cstdint>
#include <span>

namespace lp {

// Throws lp::Error(Corrupt) unless the data holds a complete "-Y H +X W" image whose scanlines are
// either all run-length encoded (new style) or flat RGBE.
void check_hdr_structure(std::span<const uint8_t> bytes);

}  // namespace lp

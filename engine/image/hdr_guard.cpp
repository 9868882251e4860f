#include "engine/image/hdr_guard.hpp"

#include <cstdio>
#include <string>
#include <string_view>

#include "engine/core/error.hpp"

namespace lp {
namespace {

[[noreturn]] void corrupt(const std::string& why) { throw Error(ErrorKind::Corrupt, "corrupt Radiance HDR: " + why); }

// Offset of the first pixel byte; fills width and height from the resolution line.
size_t parse_header(std::span<const uint8_t> b, int& width, int& height) {
  const std::string_view text(reinterpret_cast<const char*>(b.data()), b.size());
  const size_t blank = text.find("\n\n");
  if (blank == std::string_view::npos) corrupt("no end of header");
  const size_t line_start = blank + 2, line_end = text.find('\n', line_start);
  if (line_end == std::string_view::npos || line_end - line_start > 64) corrupt("no resolution line");
  const std::string line(text.substr(line_start, line_end - line_start));
  char tail = 0;
  if (std::sscanf(line.c_str(), "-Y %d +X %d%c", &height, &width, &tail) != 2)
    corrupt("unsupported resolution line '" + line + "' (expected -Y H +X W)");
  if (width <= 0 || height <= 0) corrupt("invalid size");
  return line_end + 1;
}

// One new-style RLE scanline starting at `pos`; returns the offset after it.
size_t walk_rle_scanline(std::span<const uint8_t> b, size_t pos, int width) {
  pos += 4;  // 2, 2, width high byte, width low byte (checked by the caller)
  for (int channel = 0; channel < 4; ++channel) {
    for (int filled = 0; filled < width;) {
      if (pos >= b.size()) corrupt("data ends inside a scanline");
      int count = b[pos++];
      if (count > 128) {
        count -= 128;
        pos += 1;  // the repeated value
      } else {
        if (count == 0) corrupt("zero-length run");
        pos += size_t(count);
      }
      if (count > width - filled) corrupt("run past the end of a scanline");
      filled += count;
    }
  }
  if (pos > b.size()) corrupt("data ends inside a scanline");
  return pos;
}

bool is_rle_start(std::span<const uint8_t> b, size_t pos, int width) {
  return pos + 4 <= b.size() && b[pos] == 2 && b[pos + 1] == 2 && !(b[pos + 2] & 0x80) &&
         ((int(b[pos + 2]) << 8) | b[pos + 3]) == width;
}

}  // namespace

void check_hdr_structure(std::span<const uint8_t> b) {
  int width = 0, height = 0;
  size_t pos = parse_header(b, width, height);
  const bool rle = width >= 8 && width < 32768 && is_rle_start(b, pos, width);
  if (!rle) {  // flat RGBE throughout
    if (b.size() - pos < size_t(width) * size_t(height) * 4) corrupt("data ends before the last pixel");
    return;
  }
  for (int y = 0; y < height; ++y) {
    if (!is_rle_start(b, pos, width)) corrupt("scanline " + std::to_string(y) + " is not run-length encoded like the first");
    pos = walk_rle_scanline(b, pos, width);
  }
}

}  // namespace lp

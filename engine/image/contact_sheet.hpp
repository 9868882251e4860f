#pragma once
// A contact sheet: frames of one size tiled left to right, top to bottom, in a near-square grid, with
// no gaps or labels (a frame's index is its place: row * columns + column). Cells past the last frame
// are black (transparent with 4 channels).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/image/pixels8.hpp"

namespace lp {

struct SheetLayout {
  int columns = 1;
  int rows = 1;
};

// ceil(sqrt(frames)) columns and as many rows as the frames need.
SheetLayout contact_sheet_layout(int frames);

// The sheet, (columns * width) x (rows * height) pixels of the frames' channels.
std::vector<uint8_t> contact_sheet(std::span<const Pixels8> frames, SheetLayout layout);

}  // namespace lp

#pragma once
// How an image is cut into tiles the network runs on: each tile's origin and size are multiples of 16 (the
// network pools four times), and neighbouring tiles overlap by more than half the network's receptive field,
// so that the pixels a tile writes see the same inputs as they would in one whole-image pass.
#include <vector>

namespace lp::denoise {

inline constexpr int kTileAlignment = 16;
inline constexpr int kReceptiveField = 174;  // of OIDN's U-Net, in pixels
inline constexpr int kTileOverlap =
    (kReceptiveField / 2 + kTileAlignment - 1) / kTileAlignment * kTileAlignment;
inline constexpr int kMinTileSize = 2 * kTileOverlap + kTileAlignment;

struct Tile {
  int in_x = 0, in_y = 0, in_width = 0, in_height = 0;      // what the network reads (zero past the image)
  int out_x = 0, out_y = 0, out_width = 0, out_height = 0;  // what it writes, inside the image
};

inline int round_up(int v, int to) {
  return (v + to - 1) / to * to;
}

// Tiles no larger than `tile_size` (a multiple of 16, at least kMinTileSize) on a side, covering the image.
std::vector<Tile> plan_tiles(int width, int height, int tile_size);

}  // namespace lp::denoise

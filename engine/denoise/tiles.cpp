#include "engine/denoise/tiles.hpp"

#include <algorithm>

namespace lp::denoise {
namespace {

struct Span {
  int in_begin, in_end, out_begin, out_end;
};

// Cuts [0, length) padded to a multiple of the alignment into spans of at most tile_size.
std::vector<Span> plan_axis(int length, int tile_size) {
  const int padded = round_up(length, kTileAlignment);
  if (padded <= tile_size) return {{0, padded, 0, length}};
  const int max_core = (tile_size - 2 * kTileOverlap) / kTileAlignment * kTileAlignment;
  const int count = (padded + max_core - 1) / max_core;
  const int core = round_up((padded + count - 1) / count, kTileAlignment);
  std::vector<Span> spans;
  for (int begin = 0; begin < length; begin += core) {
    const int end = std::min(begin + core, padded);
    spans.push_back({std::max(0, begin - kTileOverlap), std::min(padded, end + kTileOverlap), begin,
                     std::min(end, length)});
  }
  return spans;
}

}  // namespace

std::vector<Tile> plan_tiles(int width, int height, int tile_size) {
  std::vector<Tile> tiles;
  for (const Span& r : plan_axis(height, tile_size))
    for (const Span& c : plan_axis(width, tile_size))
      tiles.push_back({c.in_begin, r.in_begin, c.in_end - c.in_begin, r.in_end - r.in_begin, c.out_begin,
                       r.out_begin, c.out_end - c.out_begin, r.out_end - r.out_begin});
  return tiles;
}

}  // namespace lp::denoise

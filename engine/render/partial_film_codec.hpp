#pragma once
// The bytes of a range's partial film, as a worker sends it: "LPPF", a version, the size, the sample
// range, the auxiliary passes it holds (bits of 1 << AuxPass), the rays traced, then per pixel three
// float sums, the auxiliary channels' float sums and a sample count (little endian). A range's
// sums were added in float by the renderer, so float holds them exactly; merging goes to double.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/render/partial_film.hpp"

namespace lp::render {

struct RangePartial {
  SampleRange range;
  uint64_t rays = 0;  // rays traced for it (camera, bounce, shadow)
  PartialFilm film;   // every pixel holds range.count() samples
};

std::vector<uint8_t> encode_partial(const RangePartial& partial);
// Throws lp::Error(Corrupt) for bytes that are not a whole, consistent partial, and (TooLarge) for one
// of more than `max_pixels` pixels, before allocating.
RangePartial decode_partial(std::span<const uint8_t> bytes, int64_t max_pixels);

}  // namespace lp::render

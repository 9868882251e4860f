#pragma once
// Recursive subdivision of the whole map into `count` regions.
// A power of two is Debevec's classic scheme: every region is cut, level after level, k times.
// Any other count cuts the region with the most energy next (ties: the one with more pixels).
// Regions of one pixel are never cut; if that leaves a level short, the most energetic splittable
// regions are cut until there are `count` (possible whenever count <= the number of pixels).
#include <vector>

#include "engine/mediancut/region.hpp"
#include "engine/mediancut/region_splitter.hpp"

namespace lp {

// count must be in [1, width * height] (MedianCutParams::validate checks it).
std::vector<Region> subdivide(const RegionSplitter& splitter, int width, int height, int count);

}  // namespace lp

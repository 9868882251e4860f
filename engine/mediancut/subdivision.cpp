#include "engine/mediancut/subdivision.hpp"

#include <bit>
#include <optional>
#include <queue>
#include <utility>

#include <tbb/parallel_for.h>

namespace lp {
namespace {

// One level of the classic scheme: every splittable region is cut (in parallel; the cuts are
// independent), keeping the order stable.
std::vector<Region> cut_all(const RegionSplitter& splitter, const std::vector<Region>& regions) {
  std::vector<std::pair<Region, std::optional<Region>>> halves(regions.size());
  tbb::parallel_for(size_t{0}, regions.size(), [&](size_t i) {
    if (!regions[i].splittable()) {
      halves[i] = {regions[i], std::nullopt};
      return;
    }
    const auto [a, b] = splitter.split(regions[i]);
    halves[i] = {a, b};
  });
  std::vector<Region> out;
  out.reserve(regions.size() * 2);
  for (const auto& [a, b] : halves) {
    out.push_back(a);
    if (b) out.push_back(*b);
  }
  return out;
}

struct Ranked {
  double energy;
  int64_t pixels;
  Region region;
  bool operator<(const Ranked& o) const { return energy != o.energy ? energy < o.energy : pixels < o.pixels; }
};

// Cuts the most energetic splittable region until there are `count`.
std::vector<Region> cut_greedily(const RegionSplitter& splitter, std::vector<Region> regions, size_t count) {
  std::priority_queue<Ranked> queue;
  std::vector<Region> done;
  for (const Region& r : regions) {
    if (r.splittable()) queue.push({splitter.energy(r), r.pixel_count(), r});
    else done.push_back(r);
  }
  while (queue.size() + done.size() < count && !queue.empty()) {
    const Region r = queue.top().region;
    queue.pop();
    const auto [a, b] = splitter.split(r);
    for (const Region& half : {a, b}) {
      if (half.splittable()) queue.push({splitter.energy(half), half.pixel_count(), half});
      else done.push_back(half);
    }
  }
  for (; !queue.empty(); queue.pop()) done.push_back(queue.top().region);
  return done;
}

}  // namespace

std::vector<Region> subdivide(const RegionSplitter& splitter, int width, int height, int count) {
  std::vector<Region> regions = {{0, 0, width, height}};
  const auto target = size_t(count);
  if (std::has_single_bit(unsigned(count))) {
    for (int level = std::countr_zero(unsigned(count)); level > 0; --level) regions = cut_all(splitter, regions);
    if (regions.size() == target) return regions;
  }
  return cut_greedily(splitter, std::move(regions), target);
}

}  // namespace lp

#pragma once
// Cuts one region in two, from summed-area tables:
// - median: along the longer side (width measured at the latitude of the region's centre), at the
//   position that makes the halves' energies most nearly equal, found by binary search;
// - variance (Viriyothai & Debevec 2009): the cut, along either side, that minimises the larger of
//   the halves' variances sum(w * d^2), d the angular distance to the half's centroid, also found
//   by binary search (a half's variance only grows as the half grows).
#include <utility>

#include "engine/core/enum_table.hpp"
#include "engine/mediancut/moment_tables.hpp"
#include "engine/mediancut/region.hpp"
#include "engine/mediancut/summed_area_table.hpp"

namespace lp {

enum class SplitRule { Median, Variance };
constexpr auto enum_entries(SplitRule) {
  return std::to_array<EnumEntry<SplitRule>>(
      {{SplitRule::Median, "median"}, {SplitRule::Variance, "variance"}});
}

struct Cut {
  bool vertical =
      true;  // true: at column `position` (children [x0, p) and [p, x1)); false: at row `position`
  int position = 0;
};

class RegionSplitter {
 public:
  // `moments` is needed (non-null) for SplitRule::Variance only.
  RegionSplitter(const SummedAreaTable& weight, const MomentTables* moments, SplitRule rule);

  double energy(const Region& r) const { return weight_.sum(r.x0, r.y0, r.x1, r.y1); }
  // The region must be splittable (more than one pixel).
  Cut choose_cut(const Region& r) const;
  std::pair<Region, Region> split(const Region& r) const;

  // True if the region's width, in radians at the latitude of its centre, exceeds its height.
  bool wider_than_tall(const Region& r) const;

 private:
  Cut median_cut(const Region& r, bool vertical) const;
  Cut variance_cut(const Region& r) const;
  double variance(const Region& r, double sx2, double sy2) const;

  const SummedAreaTable& weight_;
  const MomentTables* moments_;
  SplitRule rule_;
  int width_, height_;
};

std::pair<Region, Region> apply_cut(const Region& r, const Cut& cut);

}  // namespace lp

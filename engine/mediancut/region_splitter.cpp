#include "engine/mediancut/region_splitter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"

namespace lp {
namespace {

// Smallest p in [lo, hi] with pred(p), or hi if none (pred must be monotone: false... then true...).
template <class Pred>
int first_true(int lo, int hi, Pred pred) {
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (pred(mid)) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}

// The better of positions p and p - 1 (if p - 1 >= lo) by `cost`; ties go to the one nearer `middle`.
template <class Cost>
int better_neighbour(int p, int lo, double middle, Cost cost) {
  if (p - 1 < lo) return p;
  const double a = cost(p - 1), b = cost(p);
  if (a < b) return p - 1;
  if (b < a) return p;
  return std::abs(p - 1 - middle) < std::abs(p - middle) ? p - 1 : p;
}

}  // namespace

std::pair<Region, Region> apply_cut(const Region& r, const Cut& cut) {
  if (cut.vertical) return {{r.x0, r.y0, cut.position, r.y1}, {cut.position, r.y0, r.x1, r.y1}};
  return {{r.x0, r.y0, r.x1, cut.position}, {r.x0, cut.position, r.x1, r.y1}};
}

RegionSplitter::RegionSplitter(const SummedAreaTable& weight, const MomentTables* moments, SplitRule rule)
    : weight_(weight), moments_(moments), rule_(rule), width_(weight.width()), height_(weight.height()) {
  if (rule == SplitRule::Variance && !moments)
    throw Error(ErrorKind::InvalidArgument, "the variance split needs the moment tables");
}

bool RegionSplitter::wider_than_tall(const Region& r) const {
  const double centre_theta = kPi * 0.5 * (r.y0 + r.y1) / height_;
  const double angular_width = r.width() * (2.0 * kPi / width_) * std::sin(centre_theta);
  const double angular_height = r.height() * (kPi / height_);
  return angular_width > angular_height;
}

Cut RegionSplitter::choose_cut(const Region& r) const {
  if (!r.splittable()) throw Error(ErrorKind::InvalidArgument, "cannot cut a region of one pixel");
  if (rule_ == SplitRule::Variance && energy(r) > 0) return variance_cut(r);
  const bool vertical = r.height() == 1 || (r.width() > 1 && wider_than_tall(r));
  return median_cut(r, vertical);
}

std::pair<Region, Region> RegionSplitter::split(const Region& r) const { return apply_cut(r, choose_cut(r)); }

// Energy below the cut grows with the cut position: binary search for the first position where the
// first half holds at least half, then take it or its predecessor, whichever is closer to half.
Cut RegionSplitter::median_cut(const Region& r, bool vertical) const {
  const int lo = (vertical ? r.x0 : r.y0) + 1, hi = (vertical ? r.x1 : r.y1) - 1;
  const double middle = 0.5 * (lo - 1 + hi + 1);
  const double total = energy(r);
  if (!(total > 0)) return {vertical, int(std::lround(std::clamp(middle, double(lo), double(hi))))};
  auto first_half = [&](int p) {
    return vertical ? weight_.sum(r.x0, r.y0, p, r.y1) : weight_.sum(r.x0, r.y0, r.x1, p);
  };
  const int p = first_true(lo, hi, [&](int q) { return 2.0 * first_half(q) >= total; });
  const int best = better_neighbour(p, lo, middle, [&](int q) { return std::abs(2.0 * first_half(q) - total); });
  return {vertical, best};
}

// sum(w * d^2) about the region's own centroid, with d measured in radians: x scaled by sx
// (radians per pixel at the parent's latitude), y by sy. Passed as squares.
double RegionSplitter::variance(const Region& r, double sx2, double sy2) const {
  const double w = weight_.sum(r.x0, r.y0, r.x1, r.y1);
  if (!(w > 0)) return 0.0;
  const double wx = moments_->wx.sum(r.x0, r.y0, r.x1, r.y1), wy = moments_->wy.sum(r.x0, r.y0, r.x1, r.y1);
  const double wxx = moments_->wxx.sum(r.x0, r.y0, r.x1, r.y1), wyy = moments_->wyy.sum(r.x0, r.y0, r.x1, r.y1);
  return sx2 * std::max(0.0, wxx - wx * wx / w) + sy2 * std::max(0.0, wyy - wy * wy / w);
}

// One metric (the parent's) for both halves keeps each half's variance monotone in the cut position,
// so the minimum of the larger one is where they cross: a binary search per axis.
Cut RegionSplitter::variance_cut(const Region& r) const {
  const double sx = (2.0 * kPi / width_) * std::sin(kPi * 0.5 * (r.y0 + r.y1) / height_);
  const double sy = kPi / height_;
  const double sx2 = sx * sx, sy2 = sy * sy;
  auto larger = [&](const Cut& c) {
    const auto [a, b] = apply_cut(r, c);
    return std::max(variance(a, sx2, sy2), variance(b, sx2, sy2));
  };
  auto best_along = [&](bool vertical) {
    const int lo = (vertical ? r.x0 : r.y0) + 1, hi = (vertical ? r.x1 : r.y1) - 1;
    const double middle = 0.5 * (lo - 1 + hi + 1);
    const int p = first_true(lo, hi, [&](int q) {
      const auto [a, b] = apply_cut(r, {vertical, q});
      return variance(a, sx2, sy2) >= variance(b, sx2, sy2);
    });
    return Cut{vertical, better_neighbour(p, lo, middle, [&](int q) { return larger({vertical, q}); })};
  };
  if (r.width() == 1) return best_along(false);
  if (r.height() == 1) return best_along(true);
  const Cut v = best_along(true), h = best_along(false);
  const double cv = larger(v), ch = larger(h);
  if (cv != ch) return cv < ch ? v : h;
  return wider_than_tall(r) ? v : h;
}

}  // namespace lp

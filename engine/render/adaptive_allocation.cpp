#include "engine/render/adaptive_allocation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace lp::render {
namespace {

__extension__ typedef unsigned __int128 Sum;
__extension__ typedef __int128 Signed;

// Weights in fixed point (units of 2^-16, saturating at 2^40), so that sums are exact.
uint64_t fixed_point(float weight) {
  if (!(weight > 0)) return 0;
  return uint64_t(std::min(double(weight), 0x1p40) * 0x1p16);
}

// The largest and the second largest weight around one pixel (itself left out), and where the
// largest is: without pixel `argmax` the weight is `second`, without any other pixel `first`.
struct Neighbourhood {
  uint64_t first = 0, second = 0;
  int64_t argmax = -1;
};

template <class Visit>
void for_each_neighbour(int x, int y, int width, int height, Visit&& visit) {
  for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
    for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
      if (nx != x || ny != y) visit(int64_t(ny) * width + nx);
}

std::vector<Neighbourhood> neighbourhoods(const std::vector<uint64_t>& q, int width, int height) {
  std::vector<Neighbourhood> out(q.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Neighbourhood& n = out[size_t(y) * size_t(width) + size_t(x)];
      for_each_neighbour(x, y, width, height, [&](int64_t j) {
        const uint64_t v = q[size_t(j)];
        if (n.argmax < 0 || v > n.first) {
          n.second = n.first;
          n.first = v;
          n.argmax = j;
        } else {
          n.second = std::max(n.second, v);
        }
      });
    }
  return out;
}

// A share that pixel i's weight set: `from` with it, `to` without (a neighbour whose largest
// neighbouring weight is pixel i's). Pixel i has at most 8 of them.
struct Change {
  uint64_t from, to;
};

// The shares as if pixel i had weight 0: every share, with pixel i's changes made, and their sum.
struct WithoutPixel {
  std::span<const Change> changes;
  Sum total;
};

// Which shares reach the cap: those of `threshold` or more (none if it is kNone), `capped` of them;
// `rest` sums the others. `after` is where the search for it ended among the largest shares.
struct Level {
  static constexpr uint64_t kNone = std::numeric_limits<uint64_t>::max();
  uint64_t threshold = kNone;
  int64_t capped = 0;
  Sum rest = 0;
  size_t after = 0;
};

// Water-filling: pixel j's count is min(a + k s_j, C) for its share s_j, the even part a of the mean
// and the cap C, with the one k that makes the counts sum to the budget. Shares at or above a
// threshold reach the cap, k shares what is left among the others. Which shares reach the cap is found
// exactly, in integers (the rule's fractions in units of 2^-24), so that it is a function of the
// shares alone, whichever pixel's weight they leave out.
class WaterFill {
 public:
  WaterFill(std::span<const uint64_t> shares, uint64_t budget, const AdaptiveRule& rule)
      : pixels_(int64_t(shares.size())),
        uniform_(std::llround(rule.uniform_share * kUnit)),
        cap_(std::llround(rule.cap * kUnit)),
        budget_(double(budget)),
        even_(budget_ * double(uniform_) / (double(pixels_) * kUnit)),
        cap_count_(budget_ * double(cap_) / (double(pixels_) * kUnit)) {
    // A share that reaches the cap has at most pixels / cap shares at or above it, and pixel i's
    // changes move at most 8 more below it: the shares beyond the largest pixels / cap + 9 never do.
    const size_t kept = std::min(shares.size(), size_t(double(shares.size()) / rule.cap) + 9);
    top_.assign(shares.begin(), shares.end());
    std::nth_element(top_.begin(), top_.begin() + std::ptrdiff_t(kept) - 1, top_.end(), std::greater<>());
    top_.resize(kept);
    std::sort(top_.begin(), top_.end(), std::greater<>());
    prefix_.resize(kept + 1);
    for (size_t r = 0; r < kept; ++r) prefix_[r + 1] = prefix_[r] + top_[r];
    ties_end_.resize(kept);
    for (size_t r = kept; r-- > 0;)
      ties_end_[r] = r + 1 < kept && top_[r + 1] == top_[r] ? ties_end_[r + 1] : r + 1;
    partial_ = kept < shares.size();
  }

  // The level of shares `w`. Leaving a weight out only lowers shares, so every top_[r] that fits with
  // all the weights (r < everyone.after) fits without pixel i's: the search starts there.
  Level level(const WithoutPixel& w, const Level& everyone = {}) const {
    size_t lo = everyone.after, hi = top_.size();  // top_[r] fits for r < lo and not for r >= hi
    for (size_t step = 1; lo < hi; step *= 2) {    // galloping, then bisection
      const size_t probe = std::min(lo + step, hi) - 1;
      if (!fits(top_[probe], tally_at(probe, w), w)) {
        hi = probe;
        break;
      }
      lo = probe + 1;
    }
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (fits(top_[mid], tally_at(mid, w), w))
        lo = mid + 1;
      else
        hi = mid;
    }
    uint64_t threshold = lo > 0 ? top_[lo - 1] : Level::kNone;
    // A changed share between the last top_ that fits and the first that does not may fit too.
    const uint64_t floor = lo < top_.size() ? top_[lo] : 0;
    for (const Change& c : w.changes)
      if (c.to > floor && c.to < threshold && fits(c.to, tally(c.to, w), w)) threshold = c.to;
    if (threshold == Level::kNone) return {Level::kNone, 0, w.total, lo};
    const Tally t = tally(threshold, w);
    return {threshold, t.count, w.total - t.sum, lo};
  }

  // The scale k of a level: what is left after the capped shares and the even part, over the rest.
  double scale(const Level& level) const {
    if (level.rest == 0) return 0;
    const double left = budget_ - double(level.capped) * cap_count_ - double(pixels_ - level.capped) * even_;
    return left / double(level.rest);
  }

  // The expected count of a pixel of share `share` at `level`, whose scale is k.
  double count(const Level& level, double k, uint64_t share) const {
    if (share >= level.threshold) return cap_count_;
    const double capped = double(level.capped) * cap_count_;
    if (level.rest == 0) return (budget_ - capped) / double(pixels_ - level.capped);  // every share is 0
    return std::max(0.0, even_ + k * double(share));
  }

 private:
  static constexpr double kUnit = 0x1p24;

  struct Tally {
    int64_t count = 0;  // shares >= v
    Sum sum = 0;        // and their sum
    bool known = true;  // false past the largest shares kept
  };

  Tally changed(size_t r, uint64_t v, const WithoutPixel& w) const {
    if (partial_ && r == top_.size()) return {0, 0, false};
    Tally t{int64_t(r), prefix_[r]};
    for (const Change& c : w.changes) {
      if (c.from >= v) --t.count, t.sum -= c.from;
      if (c.to >= v) ++t.count, t.sum += c.to;
    }
    return t;
  }
  Tally tally(uint64_t v, const WithoutPixel& w) const {
    return changed(size_t(std::upper_bound(top_.begin(), top_.end(), v, std::greater<>()) - top_.begin()), v,
                   w);
  }
  Tally tally_at(size_t r, const WithoutPixel& w) const { return changed(ties_end_[r], top_[r], w); }

  // Whether the shares >= v all fit at the cap: the sum of the counts with k = (C - a) / v, at which a
  // share v just reaches the cap, is at most the budget. Multiplied out by pixels / budget and 2^24:
  // (cap - u) rest <= (pixels - capped cap - (pixels - capped) u) v.
  bool fits(uint64_t v, const Tally& t, const WithoutPixel& w) const {
    if (v == 0 || !t.known) return false;
    const Signed rest = Signed(w.total - t.sum);
    const Signed room =
        Signed(pixels_) * Signed(kUnit) - Signed(t.count) * cap_ - Signed(pixels_ - t.count) * uniform_;
    return Signed(cap_ - uniform_) * rest <= room * Signed(v);
  }

  int64_t pixels_, uniform_, cap_;
  double budget_, even_, cap_count_;
  std::vector<uint64_t> top_;     // the largest shares, decreasing
  std::vector<Sum> prefix_;       // prefix_[r]: the sum of top_[0, r)
  std::vector<size_t> ties_end_;  // ties_end_[r]: past the last share equal to top_[r]
  bool partial_ = false;          // top_ leaves shares out
};

}  // namespace

std::vector<float> allocation_weights(std::span<const float> sigma, std::span<const float> cost) {
  if (sigma.size() != cost.size())
    throw Error(ErrorKind::InvalidArgument, "allocation_weights: the deviations and costs differ in size");
  std::vector<float> w(sigma.size());
  for (size_t i = 0; i < w.size(); ++i) w[i] = sigma[i] / std::sqrt(std::max(cost[i], 1.0f));
  return w;
}

int adaptive_warmup_spp(int spp) {
  return std::min(spp, std::max(spp / 4, 2));
}

std::vector<double> expected_samples(std::span<const float> weight, int width, int height, uint64_t budget,
                                     const AdaptiveRule& rule) {
  const size_t pixels = size_t(width) * size_t(height);
  if (width < 1 || height < 1 || weight.size() != pixels)
    throw Error(ErrorKind::InvalidArgument, "expected_samples: the weights do not match the image");
  if (!(rule.cap >= 1 && rule.cap <= 1024) || !(rule.uniform_share >= 0 && rule.uniform_share <= 1))
    throw Error(ErrorKind::InvalidArgument,
                "expected_samples: a cap outside [1, 1024] or a share outside [0, 1]");
  std::vector<uint64_t> q(pixels);
  for (size_t i = 0; i < pixels; ++i) q[i] = fixed_point(weight[i]);
  const std::vector<Neighbourhood> hood = neighbourhoods(q, width, height);
  std::vector<uint64_t> shares(pixels);
  Sum total = 0;
  for (size_t i = 0; i < pixels; ++i) total += shares[i] = hood[i].first;
  const WaterFill fill(shares, budget, rule);
  const Level everyone = fill.level({{}, total});
  const double everyone_scale = fill.scale(everyone);

  std::vector<double> out(pixels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int64_t i = int64_t(y) * width + x;
      Change changes[8];
      size_t changed = 0;
      Sum without_i = total;
      for_each_neighbour(x, y, width, height, [&](int64_t k) {
        const Neighbourhood& n = hood[size_t(k)];
        if (n.argmax != i || n.first == n.second) return;
        changes[changed++] = {n.first, n.second};
        without_i -= n.first - n.second;
      });
      if (changed == 0) {
        out[size_t(i)] = fill.count(everyone, everyone_scale, shares[size_t(i)]);
        continue;
      }
      const Level level = fill.level({{changes, changed}, without_i}, everyone);
      out[size_t(i)] = fill.count(level, fill.scale(level), shares[size_t(i)]);
    }
  return out;
}

std::vector<uint32_t> allocate_samples(std::span<const float> weight, int width, int height, uint64_t budget,
                                       uint64_t seed, uint32_t pass, const AdaptiveRule& rule) {
  const std::vector<double> expected = expected_samples(weight, width, height, budget, rule);
  const uint64_t stream = mix64(seed ^ 0x6a09e667f3bcc908ULL) ^ pass;
  std::vector<uint32_t> counts(expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    const double whole = std::floor(expected[i]);
    Rng rng(stream, uint64_t(i));
    counts[i] = uint32_t(whole) + (rng.uniform_double() < expected[i] - whole ? 1u : 0u);
  }
  return counts;
}

}  // namespace lp::render

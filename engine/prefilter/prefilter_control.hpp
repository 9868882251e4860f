#pragma once
// How a caller follows and stops a long prefilter: `stop` is asked before every row of texels (true
// ends the work early), and `progress` gets the work units (texel samples) of every finished row, from
// whichever thread did the row. Both may be empty.
#include <cstdint>
#include <functional>

namespace lp {

struct PrefilterControl {
  std::function<bool()> stop;
  std::function<void(int64_t units)> progress;

  bool stopped() const { return stop && stop(); }
  void advance(int64_t units) const {
    if (progress) progress(units);
  }
};

}  // namespace lp

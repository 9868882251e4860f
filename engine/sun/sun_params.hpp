#pragma once
// What counts as a sun (engine/sun/sun_extraction.hpp): the brightest compact emitter of a map, its
// pixels the connected ones around its peak whose luminance is at least `threshold` times the peak's.
// It is a sun if those pixels fit in a cone of `max_radius_deg` and carry at least `min_share` of the
// map's luminous power.
#include <string>

namespace lp {

struct SunParams {
  double threshold = 0.05;
  double max_radius_deg = 5.0;
  double min_share = 0.05;

  // Each in its range (engine/core/limits.hpp), else lp::Error naming the field.
  void validate() const;
  std::string key() const;  // "threshold=0.05;max_radius_deg=5;min_share=0.05"
};

}  // namespace lp

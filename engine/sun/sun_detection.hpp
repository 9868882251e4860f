#pragma once
// Finding the sun of a map, without copying it (engine/sun/sun_extraction.hpp tells the steps):
// search, core, centroid and radius, the removed disc and the ring's fill, and the power the sun
// would have once removed (estimated here in double; the extraction measures it exactly).
#include <optional>
#include <string>

#include "engine/image/image.hpp"
#include "engine/mediancut/summed_area_table.hpp"
#include "engine/sun/sun.hpp"
#include "engine/sun/sun_params.hpp"

namespace lp {

struct SunDetection {
  std::optional<Sun> sun;
  std::string reason;  // why there is none

  static constexpr int64_t kMemoryBytes = int64_t(sizeof(Sun)) + 256;  // with its reason's text
};

// `weight` is the median-cut weight table of `image` in kSunLuminance. Throws lp::Error for invalid
// params.
SunDetection detect_sun(const Image& image, const SummedAreaTable& weight, const SunParams& params);

}  // namespace lp

#pragma once
// Finding the sun of a map, without copying it (engine/sun/sun_extraction.hpp tells the steps):
// search by radiance, core, centroid and radius, the removed disc and the ring's fill, and the power the sun
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

  static constexpr int64_t kMemoryBytes = int64_t(sizeof(Sun)) + 512;  // with its reason's text
};

// The brightest pixels a detection looks among, and the most spots (each grown from the brightest pixel
// not yet in an earlier spot's core) it tries.
inline constexpr int kSunCandidatePixels = 4096;
inline constexpr int kSunCandidates = 8;
// A sky has one sun: its peak is over this many times as bright as any pixel outside its removed disc
// (a studio's row of equal softboxes is no sun).
inline constexpr float kSunPeakOverElsewhere = 4;

// `weight` is the median-cut weight table of `image` in kSunLuminance. Throws lp::Error for invalid
// params.
SunDetection detect_sun(const Image& image, const SummedAreaTable& weight, const SunParams& params);

// The bytes detect_sun takes beyond grow_sun_core's: a bitmap of the pixels tried.
int64_t sun_detection_scratch_bytes(int64_t width, int64_t height);

}  // namespace lp

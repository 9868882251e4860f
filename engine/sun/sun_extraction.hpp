#pragma once
// The dominant compact emitter of a map (its sun) taken out as a light of its own, and the map without
// it (the residual):
// 1. Search by radiance: the brightest pixels of the map are the candidates, brightest first (a sun is
//    the brightest thing in the sky however little of the map's power it carries).
// 2. Core: the pixels connected to a candidate peak of at least `threshold` times its luminance. Not a
//    sun (an overcast sky, a big window, a smooth map) if they spread over more than a cone of
//    `max_radius_deg`.
// 3. The sun's direction is the core's energy centroid; its solid angle Omega the core's, and its
//    angular radius r that of the cone of that solid angle, 2 pi (1 - cos r) = Omega.
// 4. Removal: every pixel whose centre lies within R of the direction (R = the farthest core pixel
//    centre's angle + 1.5 pixels) takes the solid-angle-weighted mean radiance of the ring from R to
//    R + max(2 pixels, R / 2) around it: that is the residual map.
// 5. Compactness and brightness: not a sun if its mean luminance over its cone (its power above the
//    ring's radiance, over Omega) is under `min_contrast` times the ring's, its luminance under
//    `min_share` of the map's, or its peak not kSunPeakOverElsewhere times any pixel outside the disc. The
//    next brightest pixel outside the cores tried so far is tried then, up to kSunCandidates spots
//    (sun_detection.hpp).
// 6. The sun's power is the map's power minus the residual's, so the two add up to the map's exactly.
// A light of the sun's power spread evenly over the cone of radius r about its direction, added to the
// residual, lights a scene as the map does.
#include <memory>
#include <optional>
#include <string>

#include "engine/envmap/envmap.hpp"
#include "engine/sun/sun.hpp"
#include "engine/sun/sun_params.hpp"

namespace lp {

struct SunExtraction {
  SunParams params;
  std::optional<Sun> sun;  // none: `reason` says why
  std::string reason;
  std::shared_ptr<const EnvMap> residual;  // the map without its sun; null when there is none
  Power map_power{}, residual_power{};     // the residual's is the map's when there is no sun
  double elapsed_ms = 0;                   // this call's time
};

// The detection and the residual are cached on the map (EnvMap::derived, their bytes reserved from the
// map's budget: the residual takes the map's image size), so a repeated call and every render of the
// map share one residual; `cached` (optional) tells whether everything came from the cache. The
// residual's own derived data (its sampler, ...) reserves from the map's budget too. Throws lp::Error for
// invalid params, MemoryBudgetError when the residual does not fit.
SunExtraction extract_sun(const EnvMap& map, const SunParams& params, bool* cached = nullptr);

}  // namespace lp

#pragma once
// Debevec's median cut (SIGGRAPH 2005 poster): an environment map becomes `count` directional lights
// of (nearly) equal energy whose powers add up to the map's power. Optionally the variance-minimising
// split of Viriyothai & Debevec (2009).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/luminance.hpp"
#include "engine/mediancut/light_placement.hpp"
#include "engine/mediancut/moment_tables.hpp"
#include "engine/mediancut/region_splitter.hpp"
#include "engine/mediancut/summed_area_table.hpp"

namespace lp {

struct MedianCutParams {
  int count = 64;
  LightPlacement placement = LightPlacement::Centroid;
  SplitRule split = SplitRule::Median;
  LuminanceMode luminance = LuminanceMode::Average;

  // count in [1, the map's pixel count], else lp::Error naming `count_field`.
  void validate(int64_t pixel_count, const std::string& count_field = "count") const;

  std::string key()
      const;  // all parameters, e.g. "count=64;placement=centroid;split=median;luminance=average"
};

struct MedianCutResult {
  MedianCutParams params;
  std::vector<MedianCutLight> lights;
  Power power{};  // sum of the lights' powers: the map's power up to rounding
  double energy_min = 0, energy_max = 0;
  double elapsed_ms = 0;  // time the computation took (including any table it had to build)

  static int64_t memory_bytes(int64_t count) {
    return int64_t(sizeof(MedianCutResult)) + count * int64_t(sizeof(MedianCutLight));
  }
};

// The summed-area tables a split rule needs: the weight table always, the moment tables for the
// variance split only (four more tables: about 1.1 GB at 8192 x 4096).
struct SplitTables {
  std::shared_ptr<const SummedAreaTable> weight;
  std::shared_ptr<const MomentTables> moments;
};
SplitTables build_split_tables(const Image& image, LuminanceMode mode, SplitRule rule);
// The same, cached on the map ("sat:<mode>", "sat_moments:<mode>"): built once per (map, mode).
SplitTables split_tables(const EnvMap& map, LuminanceMode mode, SplitRule rule);

// Throws lp::Error(InvalidArgument) if count < 1 or above the number of pixels.
MedianCutResult median_cut(const Image& image, const MedianCutParams& params, const SplitTables& tables);
MedianCutResult median_cut(const EnvMap& map, const MedianCutParams& params);

// median_cut(map, params), remembered per (map, params) in the map's cache (EnvMap::derived: its
// bytes come from the map's memory budget, evicted least recently used first), so a repeated request
// is free. `hit` (optional) tells whether the result came from the cache.
std::shared_ptr<const MedianCutResult> median_cut_cached(const EnvMap& map, const MedianCutParams& params,
                                                         bool* hit = nullptr);

}  // namespace lp

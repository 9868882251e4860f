#include "engine/mediancut/median_cut.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "engine/core/validate.hpp"
#include "engine/mediancut/subdivision.hpp"

namespace lp {

void MedianCutParams::validate(int64_t pixel_count, const std::string& count_field) const {
  require(count >= 1 && count <= pixel_count, count_field,
          fmt::format("must be in [1, {}] (the map's pixel count), got {}", pixel_count, count));
}

std::string MedianCutParams::key() const {
  return fmt::format("count={};placement={};split={};luminance={}", count, enum_name(placement),
                     enum_name(split), enum_name(luminance));
}

SplitTables build_split_tables(const Image& image, LuminanceMode mode, SplitRule rule) {
  SplitTables t;
  t.weight = std::make_shared<const SummedAreaTable>(build_weight_table(image, mode));
  if (rule == SplitRule::Variance)
    t.moments = std::make_shared<const MomentTables>(build_moment_tables(image, mode));
  return t;
}

SplitTables split_tables(const EnvMap& map, LuminanceMode mode, SplitRule rule) {
  const std::string name = enum_name(mode);
  SplitTables t;
  const int64_t w = map.width(), h = map.height();
  t.weight = map.derived<SummedAreaTable>("sat:" + name, SummedAreaTable::memory_bytes(w, h), [&] {
    return std::make_shared<const SummedAreaTable>(build_weight_table(map.image(), mode));
  });
  if (rule == SplitRule::Variance)
    t.moments = map.derived<MomentTables>("sat_moments:" + name, MomentTables::memory_bytes(w, h), [&] {
      return std::make_shared<const MomentTables>(build_moment_tables(map.image(), mode));
    });
  return t;
}

MedianCutResult median_cut(const Image& image, const MedianCutParams& params, const SplitTables& tables) {
  params.validate(image.pixel_count());
  const auto start = std::chrono::steady_clock::now();
  const RegionSplitter splitter(*tables.weight, tables.moments.get(), params.split);
  const auto regions = subdivide(splitter, image.width(), image.height(), params.count);

  MedianCutResult result;
  result.params = params;
  result.lights = place_lights(image, regions, params.placement, params.luminance);
  result.energy_min = result.lights.front().energy;
  result.energy_max = result.lights.front().energy;
  for (const auto& light : result.lights) {
    for (int c = 0; c < 3; ++c) result.power[c] += light.power[c];
    result.energy_min = std::min(result.energy_min, light.energy);
    result.energy_max = std::max(result.energy_max, light.energy);
  }
  result.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

MedianCutResult median_cut(const EnvMap& map, const MedianCutParams& params) {
  const auto start = std::chrono::steady_clock::now();
  MedianCutResult result = median_cut(map.image(), params, split_tables(map, params.luminance, params.split));
  result.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::shared_ptr<const MedianCutResult> median_cut_cached(const EnvMap& map, const MedianCutParams& params,
                                                         bool* hit) {
  if (hit) *hit = true;
  return map.derived<MedianCutResult>(
      "median_cut:" + params.key(), MedianCutResult::memory_bytes(params.count), [&] {
        if (hit) *hit = false;
        return std::make_shared<const MedianCutResult>(median_cut(map, params));
      });
}

}  // namespace lp

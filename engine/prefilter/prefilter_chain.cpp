#include "engine/prefilter/prefilter_chain.hpp"

#include "engine/envmap/latlong_resample.hpp"
#include "engine/prefilter/level_fill.hpp"
#include "engine/prefilter/lobe_convolution.hpp"
#include "engine/prefilter/prefilter_source.hpp"
#include "engine/prefilter/texel_grid.hpp"

namespace lp {
namespace {

int64_t texels(const PrefilterParams& params, int level) {
  const LevelSize s = latlong_level_size(params.base_size, level);
  return int64_t(s.width) * s.height;
}

}  // namespace

int64_t prefilter_work_units(const PrefilterParams& params) {
  int64_t units = texels(params, 0);
  for (int i = 1; i < params.levels; ++i) units += texels(params, i) * params.samples;
  return units;
}

int64_t prefiltered_chain_bytes(const PrefilterParams& params) {
  int64_t bytes = 0;
  for (int i = 0; i < params.levels; ++i) {
    const LevelSize s = latlong_level_size(params.base_size, i);
    bytes += EnvMap::image_bytes(s.width, s.height);
  }
  return bytes;
}

int64_t prefilter_working_bytes(int map_width, int map_height, const PrefilterParams& params) {
  const LevelSize base = latlong_level_size(params.base_size, 0);
  int64_t bytes =
      prefiltered_chain_bytes(params) + resample_latlong_bytes(map_height, base.width, base.height);
  if (params.levels > 1)
    bytes +=
        PrefilterSource::memory_bytes(map_width, map_height, PrefilterSource::width_for(map_width, params));
  return bytes;
}

std::optional<PrefilteredChain> prefilter_latlong(const EnvMap& map, const PrefilterParams& params,
                                                  const PrefilterControl& control) {
  params.validate();
  PrefilteredChain chain{params, 0, {}};
  const LevelSize base = latlong_level_size(params.base_size, 0);
  chain.levels.push_back(resample_latlong(map.image(), base.width, base.height));
  control.advance(texels(params, 0));
  if (params.levels < 2) return chain;
  const PrefilterSource source(map, PrefilterSource::width_for(map.width(), params));
  chain.source_width = source.width();
  for (int i = 1; i < params.levels; ++i) {
    const LevelSize size = latlong_level_size(params.base_size, i);
    const LobeConvolution convolution(source, params.roughness(i), params.samples);
    if (!fill_level(convolution, latlong_grid(size.width, size.height), chain.levels.emplace_back(), control,
                    params.samples))
      return std::nullopt;
  }
  return chain;
}

}  // namespace lp

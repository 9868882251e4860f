#include "engine/prefilter/prefilter_chain.hpp"

#include "engine/envmap/latlong_resample.hpp"
#include "engine/prefilter/level_fill.hpp"
#include "engine/prefilter/lobe_convolution.hpp"
#include "engine/prefilter/prefilter_source.hpp"
#include "engine/prefilter/texel_grid.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/reproject.hpp"

namespace lp {
namespace {

// The projection the texels are computed in: a cross is computed as the strip of its faces.
Projection computed_projection(Projection projection) {
  return projection == Projection::Cross ? Projection::Cube : projection;
}

ImageShape computed_shape(const PrefilterParams& params, int level) {
  return projection_shape(computed_projection(params.projection), prefilter_level_size(params, level));
}

int64_t texels(const PrefilterParams& params, int level) {
  const ImageShape s = computed_shape(params, level);
  return int64_t(s.width) * s.height;
}

Image level_zero(const EnvMap& map, const PrefilterParams& params) {
  const ImageShape shape = computed_shape(params, 0);
  if (params.projection == Projection::LatLong)
    return resample_latlong(map.image(), shape.width, shape.height);
  return reproject(map.image(), Projection::LatLong, computed_projection(params.projection),
                   params.base_size);
}

// What making level 0 takes beside the level: the map resampled in columns (lat-long), or the strip a
// cross is laid out from (a resampling into another projection works in the level itself).
int64_t level_zero_bytes(int map_height, const PrefilterParams& params) {
  const ImageShape base = computed_shape(params, 0);
  if (params.projection == Projection::LatLong)
    return resample_latlong_bytes(map_height, base.width, base.height);
  return params.projection == Projection::Cross ? EnvMap::image_bytes(base.width, base.height) : 0;
}

void lay_out(std::vector<Image>& levels, Projection projection) {
  if (projection != Projection::Cross) return;
  for (Image& level : levels) level = cube_relayout(level, Projection::Cube, Projection::Cross);
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
    const ImageShape s = prefilter_level_shape(params, i);
    bytes += EnvMap::image_bytes(s.width, s.height);
  }
  return bytes;
}

int64_t prefilter_working_bytes(int map_width, int map_height, const PrefilterParams& params) {
  int64_t bytes = prefiltered_chain_bytes(params) + level_zero_bytes(map_height, params);
  if (params.levels > 1)
    bytes +=
        PrefilterSource::memory_bytes(map_width, map_height, PrefilterSource::width_for(map_width, params));
  return bytes;
}

std::optional<PrefilteredChain> prefilter_chain(const EnvMap& map, const PrefilterParams& params,
                                                const PrefilterControl& control) {
  params.validate();
  PrefilteredChain chain{params, 0, {}};
  chain.levels.push_back(level_zero(map, params));
  control.advance(texels(params, 0));
  if (params.levels > 1) {
    const PrefilterSource source(map, PrefilterSource::width_for(map.width(), params));
    chain.source_width = source.width();
    for (int i = 1; i < params.levels; ++i) {
      const LobeConvolution convolution(source, params.roughness(i), params.samples);
      const TexelGrid grid =
          projection_grid(computed_projection(params.projection), computed_shape(params, i));
      if (!fill_level(convolution, grid, chain.levels.emplace_back(), control, params.samples))
        return std::nullopt;
    }
  }
  lay_out(chain.levels, params.projection);
  return chain;
}

}  // namespace lp

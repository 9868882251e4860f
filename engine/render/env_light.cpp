#include "engine/render/env_light.hpp"

#include <cmath>
#include <string>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

// A map's coarser levels and the importance grid made from the coarsest: built once per map and grid
// width, shared by every render of that map, its bytes reserved from the map's budget.
struct CoarseGrid {
  std::shared_ptr<const EnvMapLevels> levels;
  std::shared_ptr<const EnvMap> grid;
  std::shared_ptr<const EnvMapSampler> sampler;
};

std::shared_ptr<const CoarseGrid> coarse_grid(const EnvMap& map, int max_width, SamplerWeights weights) {
  const int level = EnvMapLevels::level_for_width(map.width(), max_width);
  const int64_t bytes = EnvLight::grid_memory_bytes(map.width(), map.height(), max_width);
  const bool compensated = weights == SamplerWeights::MisCompensated;
  return map.derived<CoarseGrid>(
      "importance-grid/" + std::to_string(max_width) + (compensated ? "/compensated" : ""), bytes, [&] {
        auto g = std::make_shared<CoarseGrid>();
        g->levels = std::make_shared<EnvMapLevels>(map, level);
        g->grid = g->levels->coarsest_map();
        g->sampler = g->grid->sampler(kImportanceLuminance, weights);
        return g;
      });
}

}  // namespace

EnvLight::EnvLight(std::shared_ptr<const EnvMap> map, const Lighting& lighting)
    : map_(std::move(map)), intensity_(lighting.intensity) {
  if (!map_) throw Error(ErrorKind::InvalidArgument, "lighting: no environment map");
  lighting.validate("lighting");
  const double a = double(lighting.rotation_deg) * kPi / 180.0;
  cos_ = float(std::cos(a));
  sin_ = float(std::sin(a));
  // A black map lights nothing; it has no distribution to sample (sample_importance then gives pdf 0).
  dark_ = max_component(map_->power()) <= 0;
  const bool importance = lighting.mode == LightingMode::EnvMap && !dark_;
  const auto weights = lighting.mis_compensation ? SamplerWeights::MisCompensated : SamplerWeights::Radiance;
  if (map_->width() <= lighting.importance_max_width) {
    levels_ = std::make_shared<EnvMapLevels>(*map_, 0);
    grid_ = map_;
    if (importance) importance_ = map_->sampler(kImportanceLuminance, weights);
    return;
  }
  const auto coarse = coarse_grid(*map_, lighting.importance_max_width, weights);
  levels_ = std::shared_ptr<const EnvMapLevels>(coarse, coarse->levels.get());
  grid_ = std::shared_ptr<const EnvMap>(coarse, coarse->grid.get());
  if (importance) importance_ = std::shared_ptr<const EnvMapSampler>(coarse, coarse->sampler.get());
}

int64_t EnvLight::grid_memory_bytes(int width, int height, int max_width) {
  const int level = EnvMapLevels::level_for_width(width, max_width);
  if (level == 0) return 0;
  const int gw = std::max(1, width >> level), gh = std::max(1, height >> level);
  return EnvMapLevels::memory_bytes(width, height, level) + EnvMapSampler::memory_bytes(gw, gh);
}

Rgb EnvLight::radiance(Vec3 world_direction) const {
  return grid_->radiance(to_map(world_direction)) * intensity_;
}

Rgb EnvLight::radiance_over(const EnvPixel& p, float spread) const {
  return levels_->trilinear(p.uv, levels_->level_for_angle(spread)) * intensity_;
}

LightSample EnvLight::sample_importance(Point2 u) const {
  if (!importance_) return {};
  const EnvSample s = importance_->sample(u.x, u.y);
  return {to_world(s.direction), s.radiance * intensity_, s.pdf};
}

EnvPixel EnvLight::locate(Vec3 world_direction) const {
  const Vec3 d = to_map(world_direction);
  const latlong::Uv uv = latlong::uv(d);
  const EnvPixel p{latlong::pixel_x(uv.u, grid_->width()), latlong::pixel_y(uv.v, grid_->height()),
                   latlong::sin_theta(d), uv};
  if (importance_)
    importance_->prefetch(p.x, p.y);
  else
    __builtin_prefetch(grid_->image().row(p.y) + 3 * p.x);
  return p;
}

LightSample EnvLight::sample_uniform(Point2 u) const {
  const Vec3 d = square_to_uniform_sphere(u.x, u.y);
  return {d, radiance(d), kUniformSpherePdf};
}

}  // namespace lp::render

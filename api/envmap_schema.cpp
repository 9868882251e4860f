#include "api/envmap_schema.hpp"

#include <fmt/chrono.h>

#include <span>
#include <vector>

#include "engine/envmap/envmap_sampler.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/sampling/cdf_1d.hpp"

namespace lp::api {

Json rgb_json(Rgb c) {
  return Json::array({c.x, c.y, c.z});
}

Json envmap_metadata(const EnvMapInfo& info, const EnvMap& map) {
  return {{"id", info.id},
          {"name", info.name},
          {"width", map.width()},
          {"height", map.height()},
          {"memory_bytes", map.memory_bytes()},
          {"format", info.format},
          {"source", info.source},
          {"source_projection", enum_name(info.source_projection)},
          {"mean_radiance", rgb_json(map.mean_radiance())},
          {"max_luminance", map.max_luminance(LuminanceMode::Average)},
          {"power", rgb_json(map.power())},
          {"illuminance", upper_hemisphere_illuminance(map)},
          {"clamped_negative_values", map.invalid_pixels().clamped_negative_values},
          {"most_negative_value", map.invalid_pixels().most_negative_value},
          {"non_finite_pixels", map.invalid_pixels().non_finite_pixels},
          {"created",
           fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(info.created))}};
}

Json distribution_json(const EnvMap& map, LuminanceMode mode, bool sin_weight) {
  const auto sampler = map.sampler(mode);
  const PiecewiseConstant2D& dist = sampler->distribution();
  const int h = map.height();
  std::vector<double> row_luminance(static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) row_luminance[size_t(y)] = sampler->row_mean_luminance(y);
  // With sin weighting the rows are the sampler's own marginal distribution.
  const std::span<const double> weight = sin_weight ? dist.row_weight_sums() : std::span(row_luminance);
  std::vector<float> cdf(dist.marginal_cdf().begin(), dist.marginal_cdf().end());
  if (!sin_weight) cdf_1d::build(weight.data(), h, cdf.data());
  double total = 0;
  for (double w : weight) total += w;
  std::vector<double> pdf(static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) pdf[size_t(y)] = weight[size_t(y)] / total;
  return {{"height", h},
          {"luminance", enum_name(mode)},
          {"sin_weight", sin_weight},
          {"row_luminance", row_luminance},
          {"marginal_pdf", pdf},
          {"marginal_cdf", cdf}};
}

}  // namespace lp::api

#include "api/envmap_schema.hpp"

#include <cmath>

#include <fmt/chrono.h>

namespace lp::api {

Json rgb_json(Rgb c) { return Json::array({c.x, c.y, c.z}); }

Json envmap_metadata(const EnvMapInfo& info, const EnvMap& map) {
  return {{"id", info.id},
          {"name", info.name},
          {"width", map.width()},
          {"height", map.height()},
          {"memory_bytes", map.memory_bytes()},
          {"format", info.format},
          {"source", info.source},
          {"mean_radiance", rgb_json(map.mean_radiance())},
          {"max_luminance", map.max_luminance(LuminanceMode::Average)},
          {"power", rgb_json(map.power())},
          {"clamped_negative_values", map.invalid_pixels().clamped_negative_values},
          {"most_negative_value", map.invalid_pixels().most_negative_value},
          {"non_finite_pixels", map.invalid_pixels().non_finite_pixels},
          {"created", fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(info.created))}};
}

Json distribution_json(const EnvMap& map, LuminanceMode mode, bool sin_weight) {
  const int w = map.width(), h = map.height();
  std::vector<double> row_luminance(static_cast<size_t>(h)), weight(static_cast<size_t>(h));
  double total = 0;
  for (int y = 0; y < h; ++y) {
    const float* row = map.image().row(y);
    double sum = 0;
    for (int x = 0; x < w; ++x) sum += luminance({row[3 * x], row[3 * x + 1], row[3 * x + 2]}, mode);
    row_luminance[size_t(y)] = sum / w;
    weight[size_t(y)] = row_luminance[size_t(y)] * (sin_weight ? std::sin(latlong::row_centre_theta(y, h)) : 1.0);
    total += weight[size_t(y)];
  }
  Json pdf = Json::array(), cdf = Json::array({0.0});
  double run = 0;
  for (int y = 0; y < h; ++y) {
    const double p = total > 0 ? weight[size_t(y)] / total : 0.0;
    run += p;
    pdf.push_back(p);
    cdf.push_back(y + 1 == h && total > 0 ? 1.0 : run);
  }
  return {{"height", h},
          {"luminance", enum_name(mode)},
          {"sin_weight", sin_weight},
          {"row_luminance", row_luminance},
          {"marginal_pdf", pdf},
          {"marginal_cdf", cdf}};
}

}  // namespace lp::api

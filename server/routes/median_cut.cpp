// POST /envmaps/{id}/median-cut (the lights as JSON) and GET /envmaps/{id}/median-cut.png (pictures).
// Results are cached per (map, parameters) on the map, so a repeat request costs only the encoding.
#include <chrono>

#include "api/light_export.hpp"
#include "api/median_cut_request.hpp"
#include "api/median_cut_schema.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/mediancut/median_cut_plot.hpp"
#include "server/http/reserved_content.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

void median_cut(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto start = std::chrono::steady_clock::now();
  const auto entry = app.envmaps.get(path_param(req, 1));
  const api::LightExportQuery format = api::parse_light_export_query(req.params);
  const MedianCutParams params = api::parse_median_cut_request(req.body, app.options.limits);
  api::check_count_fits(params, entry->map->image().pixel_count());
  bool cached = false;
  const auto result = median_cut_cached(*entry->map, params, &cached);
  if (format.format != api::LightFormat::Answer) {
    const api::LightSet set = api::median_cut_light_set(*result, upper_hemisphere_illuminance(*entry->map));
    res.set_content(api::export_lights(set, format.format, format.frame),
                    api::light_format_content_type(format.format));
    return;
  }
  const double elapsed =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  res.set_content(api::median_cut_json(*result, elapsed, cached), "application/json");
}

void median_cut_png(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const auto r = api::parse_median_cut_image_query(req.params, app.options.limits);
  api::check_count_fits(r.params, entry->map->image().pixel_count());
  const auto result = median_cut_cached(*entry->map, r.params);
  const int64_t w = entry->map->width(), h = entry->map->height();
  send_png_picture(res, app.memory, w, h, median_cut_plot_bytes(w, h), "a median cut picture",
                   [&] { return plot_median_cut(entry->map->image(), *result, r.style, r.tone); });
}

}  // namespace

void register_median_cut_routes(Router& router, App& app) {
  router.post("/api/v1/envmaps/{id}/median-cut", endpoint_of(app, median_cut));
  router.get("/api/v1/envmaps/{id}/median-cut.png", endpoint_of(app, median_cut_png), Caching::Revalidate);
}

}  // namespace lp::server

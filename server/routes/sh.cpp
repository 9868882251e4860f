// GET /envmaps/{id}/sh (coefficients as JSON) and GET /envmaps/{id}/sh.png (the reconstruction as a
// lat-long picture). The projection is cached per map with all five bands; a request takes its prefix.
#include <algorithm>

#include "api/sh_request.hpp"
#include "api/sh_schema.hpp"
#include "engine/image/image_io.hpp"
#include "engine/sh/sh_image.hpp"
#include "server/http/reserved_content.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

void sh(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const api::ShRequest request = api::parse_sh_query(req.params);
  bool cached = false;
  const auto projection = sh_projection_cached(*entry->map, &cached);
  res.set_content(api::sh_json(projection->radiance, request, projection->elapsed_ms, cached),
                  "application/json");
}

void sh_png(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const api::ShImageRequest r = api::parse_sh_image_query(req.params);
  const int w = r.width.value_or(std::min(entry->map->width(), api::kDefaultShImageMaxWidth));
  const int h = std::max(1, w / 2);
  const auto projection = sh_projection_cached(*entry->map);
  ShCoefficients c = api::sh_radiance(projection->radiance, r.sh);
  if (r.quantity == api::ShQuantity::Lambertian) c = sh_lambertian(c);
  const int64_t drawing = int64_t(w) * h * (3 * int64_t(sizeof(float)) + 3);  // float image, then RGB8
  send_png_picture(res, app.memory, w, h, drawing, "an SH reconstruction picture",
                   [&] { return tone_map_rgb8(sh_reconstruction_image(c, w, h), r.tone); });
}

}  // namespace

void register_sh_routes(Router& router, App& app) {
  router.get("/api/v1/envmaps/{id}/sh", endpoint_of(app, sh));  // says whether it was cached: no ETag
  router.get("/api/v1/envmaps/{id}/sh.png", endpoint_of(app, sh_png), Caching::Revalidate);
}

}  // namespace lp::server

// POST /envmaps/{id}/sun: the map's sun, and its residual registered as the map "<id>-sun". The
// extraction and the residual are cached on the map (engine/sun), so a repeat costs nothing and renders
// with sun "extract" share the same residual. The residual map is not kept across restarts.
#include "api/api_error.hpp"
#include "api/excerpt.hpp"
#include "api/light_export.hpp"
#include "api/sun_request.hpp"
#include "api/sun_schema.hpp"
#include "engine/envmap/illuminance.hpp"
#include "server/routes/routes.hpp"
#include "server/storage/resource_name.hpp"

namespace lp::server {
namespace {

// The source of a residual map: the map it came from.
std::string residual_source(const std::string& id) {
  return "sun:" + id;
}

// The residual registered as "<id>-sun": the entry already there if it holds this residual; an earlier
// residual of the same map (other parameters, or an earlier map of that id) is replaced; a map of that
// name from elsewhere is a conflict.
std::string register_residual(App& app, const EnvMapEntry& from,
                              const std::shared_ptr<const EnvMap>& residual) {
  const std::string id = api::sun_residual_id(from.id);
  if (!valid_resource_name(id))
    throw api::ApiError(api::ErrorCode::Conflict, "the residual map's id '" + api::excerpt(id) + "' " +
                                                      std::string(kResourceNameRule) +
                                                      ": the map's id is too long");
  const std::string source = residual_source(from.id);
  if (const auto existing = app.envmaps.find(id)) {
    if (existing->map == residual) return id;
    if (existing->source != source)
      throw api::ApiError(
          api::ErrorCode::Conflict,
          "a map named '" + id + "' exists and is not the residual of '" + from.id + "'; delete it first");
    app.envmaps.remove(id);
  }
  try {
    return app.envmaps.add(id, "residual", source, residual)->id;
  } catch (const api::ApiError&) {  // a concurrent request registered it first
    if (const auto now = app.envmaps.find(id); now && now->map == residual) return id;
    throw;
  }
}

void sun(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const api::LightExportQuery format = api::parse_light_export_query(req.params);
  const SunParams params = api::parse_sun_request(req.body);
  bool cached = false;
  const SunExtraction extraction = extract_sun(*entry->map, params, &cached);
  if (format.format != api::LightFormat::Answer) {
    const double illuminance = upper_hemisphere_illuminance(*entry->map);
    const api::LightSet set = extraction.sun ? api::sun_light_set(*extraction.sun, illuminance)
                                             : api::no_sun_light_set(extraction.reason, illuminance);
    res.set_content(api::export_lights(set, format.format, format.frame),
                    api::light_format_content_type(format.format));
    return;
  }
  std::optional<std::string> residual;
  if (extraction.sun) residual = register_residual(app, *entry, extraction.residual);
  send_json(res, api::sun_json(extraction, residual, cached));
}

}  // namespace

void register_sun_routes(Router& router, App& app) {
  router.post("/api/v1/envmaps/{id}/sun", endpoint_of(app, sun));
}

}  // namespace lp::server

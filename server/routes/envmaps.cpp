// Environment maps: list, load (upload or data-dir path), metadata, delete, image, distribution.
#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/envmap_load_request.hpp"
#include "api/envmap_schema.hpp"
#include "api/preview_params.hpp"
#include "api/projection_params.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/projection_cache.hpp"
#include "engine/projection/projection_exr.hpp"
#include "server/http/reserved_content.hpp"
#include "server/maps/envmap_loading.hpp"
#include "server/maps/stored_maps.hpp"
#include "server/routes/routes.hpp"
#include "server/storage/data_dir.hpp"

namespace lp::server {
namespace {

api::Json metadata(const EnvMapEntry& e) {
  return api::envmap_metadata({e.id, e.name, e.format, e.source, e.created, e.source_projection}, *e.map);
}

InvalidPixelPolicy invalid_pixel_policy(const httplib::Request& req) {
  return *parse_enum<InvalidPixelPolicy>(api::query_enum(
      req.params, "invalid", enum_name(kDefaultInvalidPixelPolicy), enum_names<InvalidPixelPolicy>()));
}

Projection file_projection(const httplib::Request& req) {
  return api::parse_input_projection(req.params);
}

// A JSON body (load by path) must say so; anything else is an image upload.
bool is_json_body(const httplib::Request& req) {
  if (has_json_content_type(req)) return true;
  if (!req.body.empty() && req.body.front() == '{')
    throw api::ApiError(api::ErrorCode::UnsupportedMediaType,
                        "a JSON body (load by path) must be sent as Content-Type: application/json");
  return false;
}

std::shared_ptr<const EnvMapEntry> load_from_json(App& app, const httplib::Request& req) {
  const api::EnvMapLoadRequest r = api::parse_envmap_load_request(req.body);
  const auto path = resolve_in_data_dir(app.options, r.path, "path");
  return register_envmap_file(app, r.name, path, "path:" + r.path, invalid_pixel_policy(req),
                              file_projection(req));
}

std::shared_ptr<const EnvMapEntry> load_from_upload(App& app, const httplib::Request& req) {
  const auto name = api::query_string(req.params, "name");
  if (!name) throw api::invalid_field("name", "is required (?name=NAME) when the body is an image");
  if (req.body.empty())
    throw api::ApiError(api::ErrorCode::EmptyBody, "the request body is empty: send an EXR, PFM or HDR file");
  const auto* bytes = reinterpret_cast<const uint8_t*>(req.body.data());
  return register_envmap_bytes(app, *name, {bytes, req.body.size()}, "upload", invalid_pixel_policy(req),
                               file_projection(req));
}

void create(App& app, const httplib::Request& req, httplib::Response& res) {
  const bool by_path = is_json_body(req);
  const auto entry = by_path ? load_from_json(app, req) : load_from_upload(app, req);
  const auto* body = reinterpret_cast<const uint8_t*>(req.body.data());
  keep_map(app, entry, by_path ? std::span<const uint8_t>() : std::span(body, req.body.size()));
  res.set_header("Location", "/api/v1/envmaps/" + entry->id);
  send_json(res, metadata(*entry), 201);
}

void send_image(const Image& pixels, ImageFormat format, const ToneMap& tone, ExrEnvmap envmap,
                MemoryReservation memory, httplib::Response& res) {
  send_reserved(res, write_image_envmap(pixels, format, tone, envmap), format_mime_type(format),
                std::move(memory));
}

// The map in another projection, cached on it; a cross or a single face is copied out of the cube's strip.
void send_projection(App& app, const EnvMap& map, const api::ProjectionParams& params,
                     const api::PreviewParams& preview, httplib::Response& res) {
  const int size = api::projection_image_size(params, map.width(), app.options.limits.max_pixels);
  const bool copied = params.projection == Projection::Cross || params.face;
  const ImageShape shape = params.face ? ImageShape{size, size} : projection_shape(params.projection, size);
  auto memory = app.memory.reserve(
      (copied ? EnvMap::image_bytes(shape.width, shape.height) : 0) +
          encode_bytes(preview.format, shape.width, shape.height),
      MemoryUse::Transient,
      fmt::format("encoding a {} of the map as {}", enum_name(params.projection), enum_name(preview.format)));
  const auto strip_or_square = projection_cached(map, params.projection, size);
  if (!copied)
    return send_image(*strip_or_square, preview.format, preview.tone, exr_envmap(params.projection),
                      std::move(memory), res);
  const Image image = params.face ? cube_strip_face(*strip_or_square, int(*params.face))
                                  : cube_relayout(*strip_or_square, Projection::Cube, Projection::Cross);
  send_image(image, preview.format, preview.tone, ExrEnvmap::None, std::move(memory), res);
}

void image(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const auto preview = api::parse_preview_params(req.params);
  const auto projection = api::parse_projection_params(req.params);
  if (projection.projection != Projection::LatLong)
    return send_projection(app, *entry->map, projection, preview, res);
  const Image& pixels = entry->map->image();
  auto memory =
      app.memory.reserve(encode_bytes(preview.format, pixels.width(), pixels.height()), MemoryUse::Transient,
                         std::string("encoding a map as ") + enum_name(preview.format));
  send_image(pixels, preview.format, preview.tone, ExrEnvmap::LatLong, std::move(memory), res);
}

void distribution(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto entry = app.envmaps.get(path_param(req, 1));
  const auto mode =
      *parse_enum<LuminanceMode>(api::query_enum(req.params, "luminance", "average", {"average", "rec709"}));
  const bool sin_weight = api::query_bool(req.params, "sin_weight", true);
  send_json(res, api::distribution_json(*entry->map, mode, sin_weight));
}

}  // namespace

void register_envmap_routes(Router& router, App& app) {
  router.get("/api/v1/envmaps", [&app](const httplib::Request&, httplib::Response& res) {
    api::Json list = api::Json::array();
    for (const auto& e : app.envmaps.list()) list.push_back(metadata(*e));
    send_json(res, {{"envmaps", list}});
  });
  router.post("/api/v1/envmaps", endpoint_of(app, create), PostBody::JsonOrImage);
  router.get("/api/v1/envmaps/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    send_json(res, metadata(*app.envmaps.get(path_param(req, 1))));
  });
  router.del("/api/v1/envmaps/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    const std::string id = path_param(req, 1);
    if (!remove_map(app, id)) throw api::not_found("no environment map with id '" + api::excerpt(id) + "'");
    res.status = 204;
  });
  router.get("/api/v1/envmaps/{id}/image", endpoint_of(app, image), Caching::Revalidate);
  router.get("/api/v1/envmaps/{id}/distribution", endpoint_of(app, distribution), Caching::Revalidate);
}

}  // namespace lp::server

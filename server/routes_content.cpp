// GET /api/v1/content/{hash}: a map this server holds, by its content hash (envmap_fingerprint.hpp), for
// the workers of a render split over Redis (map_fetcher.hpp).
#include "api/api_error.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "server/envmap_fingerprint.hpp"
#include "server/reserved_content.hpp"
#include "server/routes.hpp"

namespace lp::server {
namespace {

void content(App& app, const httplib::Request& req, httplib::Response& res) {
  const std::string hash = path_param(req, 1);
  for (const auto& entry : app.envmaps.list()) {
    if (envmap_fingerprint(*entry->map) != hash) continue;
    const Image& pixels = entry->map->image();
    auto memory = app.memory.reserve(encode_bytes(ImageFormat::Exr, pixels.width(), pixels.height()),
                                     MemoryUse::Transient, "encoding a map for a worker");
    send_reserved(res, write_exr(pixels), format_mime_type(ImageFormat::Exr), std::move(memory));
    return;
  }
  throw api::not_found("no map of content hash '" + api::excerpt(hash) + "'");
}

}  // namespace

void register_content_routes(Router& router, App& app) {
  router.get("/api/v1/content/{hash}", endpoint_of(app, content));
}

}  // namespace lp::server

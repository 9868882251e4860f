// GET /api/v1/content/{hash}: a map this server holds, by its content hash (maps/envmap_content_hash.hpp), or
// a mesh bundle a split render of this server published (scale_out/mesh_bundles.hpp), as a tar, for the
// workers of a render split over Redis (scale_out/map_fetcher.hpp, scale_out/bundle_fetcher.hpp).
#include "api/api_error.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "server/http/reserved_content.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "server/routes/routes.hpp"
#include "server/scale_out/bundle_archive.hpp"

namespace lp::server {
namespace {

constexpr const char* kTarType = "application/x-tar";

bool send_map(App& app, const std::string& hash, httplib::Response& res) {
  for (const auto& entry : app.envmaps.list()) {
    if (envmap_content_hash(*entry->map) != hash) continue;
    const Image& pixels = entry->map->image();
    auto memory = app.memory.reserve(encode_bytes(ImageFormat::Exr, pixels.width(), pixels.height()),
                                     MemoryUse::Transient, "encoding a map for a worker");
    send_reserved(res, write_exr(pixels), format_mime_type(ImageFormat::Exr), std::move(memory));
    return true;
  }
  return false;
}

// The files as they are now: a worker checks them against the hash.
bool send_bundle(App& app, const std::string& hash, httplib::Response& res) {
  const auto bundle = app.bundles.find(hash);
  if (!bundle) return false;
  const BundleSize size = bundle_size(*bundle);
  auto memory = app.memory.reserve(size.tar_bytes + size.largest_file_bytes, MemoryUse::Transient,
                                   "writing a mesh bundle for a worker");
  send_reserved(res, write_bundle_tar(*bundle, size), kTarType, std::move(memory));
  return true;
}

void content(App& app, const httplib::Request& req, httplib::Response& res) {
  const std::string hash = path_param(req, 1);
  if (send_map(app, hash, res) || send_bundle(app, hash, res)) return;
  throw api::not_found("no map or mesh bundle of content hash '" + api::excerpt(hash) + "'");
}

}  // namespace

void register_content_routes(Router& router, App& app) {
  router.get("/api/v1/content/{hash}", endpoint_of(app, content));
}

}  // namespace lp::server

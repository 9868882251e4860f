// Model assets for scenes: list, upload (a .glb or a self-contained .gltf, or a zip or tar archive of a
// model and its textures), metadata and the model's description, delete.
#include "api/api_error.hpp"
#include "api/asset_schema.hpp"
#include "server/assets/stored_assets.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

void create(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto name = api::query_string(req.params, "name");
  if (!name) throw api::invalid_field("name", "is required (?name=NAME)");
  const auto* bytes = reinterpret_cast<const uint8_t*>(req.body.data());
  const auto asset = store_asset(app, *name, {bytes, req.body.size()});
  res.set_header("Location", "/api/v1/assets/" + asset->name);
  send_json(res, api::asset_metadata(*asset), 201);
}

}  // namespace

void register_asset_routes(Router& router, App& app) {
  router.get("/api/v1/assets", [&app](const httplib::Request&, httplib::Response& res) {
    api::Json list = api::Json::array();
    for (const auto& asset : app.assets.list()) list.push_back(api::asset_metadata(*asset));
    send_json(res, {{"assets", list}});
  });
  router.post("/api/v1/assets", endpoint_of(app, create), PostBody::File);
  router.get("/api/v1/assets/{name}", [&app](const httplib::Request& req, httplib::Response& res) {
    send_json(res, api::asset_metadata(*app.assets.get(path_param(req, 1))));
  });
  router.del("/api/v1/assets/{name}", [&app](const httplib::Request& req, httplib::Response& res) {
    const std::string name = path_param(req, 1);
    if (!remove_asset(app, name)) throw api::not_found("no asset named '" + api::excerpt(name) + "'");
    res.status = 204;
  });
}

}  // namespace lp::server

// GET /api/v1/health, GET /api/v1/openapi.yaml
#include "api/openapi.hpp"
#include "server/routes.hpp"

namespace lp::server {

void register_meta_routes(Router& router, App&) {
  router.get("/api/v1/health", [](const httplib::Request&, httplib::Response& res) {
    send_json(res, {{"status", "ok"}, {"version", LIGHTPROBE_VERSION}});
  });
  router.get("/api/v1/openapi.yaml", [](const httplib::Request&, httplib::Response& res) {
    const auto doc = api::openapi_document();
    res.set_content(doc.data(), doc.size(), "application/yaml");
  });
}

}  // namespace lp::server

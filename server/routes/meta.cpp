// GET /api/v1/health, GET /api/v1/ready, GET /api/v1/openapi.yaml
#include "api/openapi.hpp"
#include "server/http/probe_routes.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {

void register_meta_routes(Router& router, App& app) {
  router.get(std::string(kHealthPath), [&app](const httplib::Request&, httplib::Response& res) {
    const nlohmann::json memory = {{"budget_bytes", app.memory.capacity()},
                                   {"used_bytes", app.memory.used()},
                                   {"cache_bytes", app.memory.used(MemoryUse::Cache)}};
    send_json(res, {{"status", "ok"},
                    {"version", LIGHTPROBE_VERSION},
                    {"memory", memory},
                    {"denoiser", {{"available", app.denoiser.available()}}}});
  });
  router.get(std::string(kReadyPath), [&app](const httplib::Request&, httplib::Response& res) {
    if (app.ready.load())
      send_json(res, {{"status", "ready"}});
    else
      send_not_ready(res);
  });
  router.get(
      "/api/v1/openapi.yaml",
      [](const httplib::Request&, httplib::Response& res) {
        const auto doc = api::openapi_document();
        res.set_content(doc.data(), doc.size(), "application/yaml");
      },
      Caching::Fresh);
}

}  // namespace lp::server

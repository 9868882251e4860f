// GET /api/v1/fresnel: Fresnel reflectance tables of a dielectric pair or a conductor, JSON or CSV.
#include "api/fresnel_request.hpp"
#include "api/fresnel_schema.hpp"
#include "engine/fresnel/fresnel_table.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

template <typename Table, typename... Extra>
void send_table(httplib::Response& res, bool csv, const Table& table, const Extra&... extra) {
  if (csv)
    res.set_content(api::fresnel_csv(table), "text/csv");
  else
    send_json(res, api::fresnel_json(table, extra...));
}

void fresnel(const httplib::Request& req, httplib::Response& res) {
  const api::FresnelRequest r = api::parse_fresnel_query(req.params);
  if (r.conductor)
    send_table(res, r.csv, conductor_table(r.eta_i, r.conductor->eta, r.conductor->k, r.step),
               r.conductor->metal);
  else
    send_table(res, r.csv, dielectric_table(r.eta_i, r.eta_t, r.step));
}

}  // namespace

void register_fresnel_routes(Router& router, App&) {
  router.get("/api/v1/fresnel", fresnel, Caching::Fresh);
}

}  // namespace lp::server

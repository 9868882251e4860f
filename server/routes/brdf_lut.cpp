// GET /api/v1/brdf-lut: the split-sum DFG table as an image file (a pure function of the query).
#include "api/brdf_lut_request.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

void brdf_lut(const httplib::Request& req, httplib::Response& res) {
  const api::BrdfLutRequest r = api::parse_brdf_lut_query(req.params);
  const auto lut = dfg_lut_cached(r.size, r.multiscatter);
  const auto bytes = write_image(api::dfg_lut_image(*lut), r.format, api::kLinearPng);
  res.set_content(reinterpret_cast<const char*>(bytes.data()), bytes.size(), format_mime_type(r.format));
}

}  // namespace

void register_brdf_lut_routes(Router& router, App&) {
  router.get("/api/v1/brdf-lut", brdf_lut, Caching::Fresh);
}

}  // namespace lp::server

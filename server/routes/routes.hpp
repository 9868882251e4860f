#pragma once
// One function per group of endpoints; server.cpp calls them all.
#include "server/app.hpp"
#include "server/http/router.hpp"

namespace lp::server {

// The handler of an endpoint written as `void endpoint(App&, const httplib::Request&, httplib::Response&)`.
template <typename Endpoint>
Handler endpoint_of(App& app, Endpoint endpoint) {
  return [&app, endpoint](const httplib::Request& req, httplib::Response& res) { endpoint(app, req, res); };
}

void register_meta_routes(Router& router, App& app);    // health, openapi
void register_envmap_routes(Router& router, App& app);  // envmaps CRUD, image, distribution
void register_asset_routes(Router& router, App& app);   // model assets: upload, list, metadata, delete
void register_sample_routes(Router& router, App& app);  // samples, samples.png
void register_render_routes(Router& router, App& app);  // render jobs: submit, status, image, events, cancel
void register_turntable_routes(Router& router, App& app);   // turntables: submit, status, frames, outputs
void register_fresnel_routes(Router& router, App& app);     // fresnel reflectance tables
void register_median_cut_routes(Router& router, App& app);  // median-cut lights and pictures
void register_sh_routes(Router& router, App& app);          // spherical harmonics and their picture
void register_brdf_lut_routes(Router& router, App& app);    // the split-sum DFG table
void register_prefilter_routes(Router& router, App& app);   // prefiltered specular chains: jobs, files
void register_sun_routes(Router& router, App& app);         // sun extraction and its residual map
void register_metrics_routes(Router& router, App& app);     // GET /metrics (Prometheus)
void register_content_routes(Router& router, App& app);     // maps by content hash, for Redis workers

}  // namespace lp::server

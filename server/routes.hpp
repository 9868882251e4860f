#pragma once
// One function per group of endpoints; server.cpp calls them all. CONTRIBUTING.md says how to add one.
#include "server/app.hpp"
#include "server/router.hpp"

namespace lp::server {

void register_meta_routes(Router& router, App& app);     // health, openapi
void register_envmap_routes(Router& router, App& app);   // envmaps CRUD, image, distribution
void register_sample_routes(Router& router, App& app);   // samples, samples.png
void register_render_routes(Router& router, App& app);   // render jobs: submit, status, image, events, cancel
void register_fresnel_routes(Router& router, App& app);  // fresnel reflectance tables
void register_median_cut_routes(Router& router, App& app);  // median-cut lights and pictures

}  // namespace lp::server

#include "api/render_schema.hpp"

#include "api/sun_request.hpp"

namespace lp::api {

void describe_render(Json& out, const RenderRequest& request, const RenderProgress& progress) {
  const auto& s = request.settings;
  out["spp_done"] = progress.spp_done;
  out["spp"] = s.spp;
  out["width"] = s.width;
  out["height"] = s.height;
  out["max_depth"] = s.max_depth;
  out["seed"] = s.seed;
  out["mipmaps"] = s.mipmaps;
  out["normal_maps"] = s.normal_maps;
  out["sampling"] = enum_name(s.sampling);
  if (s.background.mode == render::BackgroundMode::Color)
    out["background"] = {s.background.color.x, s.background.color.y, s.background.color.z};
  else
    out["background"] = enum_name(s.background.mode);
  out["clamp"] = s.clamp ? Json(*s.clamp) : Json(nullptr);
  out["passes"] = Json::array();
  for (const auto p : s.passes.list()) out["passes"].push_back(enum_name(p));
  out["envmap"] = request.envmap;
  out["scene"] =
      request.preset ? Json{{"preset", *request.preset}} : Json{{"objects", request.scene.objects.size()}};
  out["lighting_mode"] = enum_name(request.lighting.mode);
  out["lighting_sun"] = enum_name(request.lighting.sun);
  out["lighting_sun_parameters"] = sun_params_json(request.lighting.sun_parameters);
  const auto& stats = progress.stats;
  out["samples"] = stats.samples;
  out["rays"] = stats.rays;
  out["samples_per_s"] = progress.render_s > 0 ? double(stats.samples) / progress.render_s : 0.0;
  out["rays_per_s"] = progress.render_s > 0 ? double(stats.rays) / progress.render_s : 0.0;
  out["image_available"] = progress.image_available;
  out["denoise"] = request.denoise;
  out["denoised"] = request.denoise
                        ? Json{{"ready", progress.denoise_s.has_value()},
                               {"seconds", progress.denoise_s ? Json(*progress.denoise_s) : Json()}}
                        : Json();
  if (request.view) {
    const render::Camera& c = request.view->camera;
    out["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                     {"look_at", {c.look_at.x, c.look_at.y, c.look_at.z}},
                     {"up", {c.up.x, c.up.y, c.up.z}},
                     {"fov_deg", c.fov_deg}};
    out["warnings"] = request.view->warnings;
  }
}

}  // namespace lp::api

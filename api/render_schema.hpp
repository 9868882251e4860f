#pragma once
// What a render job's status says about the render: its settings, map and scene as accepted, and how far
// it has come (samples per pixel done, what it traced and how fast).
#include <optional>

#include "api/params.hpp"
#include "api/render_request.hpp"
#include "engine/render/renderer.hpp"

namespace lp::api {

struct RenderProgress {
  int spp_done = 0;
  render::RenderStats stats;  // over every run of the render
  double render_s = 0;        // time spent in passes, for the rates
  bool image_available = false;
  std::optional<double> denoise_s;  // the denoise's time, once the denoised image is ready
};

void describe_render(Json& out, const RenderRequest& request, const RenderProgress& progress);

}  // namespace lp::api

#pragma once
// The passes a progressive render runs: small ones first, so an image shows soon, then larger ones.
#include <vector>

#include "engine/render/scene_desc.hpp"

namespace lp::render {

// Samples per pixel of each pass: 1, 1, 2, 4, ... doubling up to `max_pass`, then `max_pass` until done
// (the last pass takes the remainder). Sums to `spp`.
std::vector<int> pass_schedule(int spp, int max_pass = 32);

// A render's passes, and whether each one is adaptive (Renderer::render_adaptive_pass). An adaptive
// render first renders its uniform warm-up (adaptive_warmup_spp, on which the pixels' noise is
// measured) in passes of pass_schedule, then the rest in adaptive passes of pass_schedule.
struct RenderPass {
  int spp;
  bool adaptive;
};
std::vector<RenderPass> render_passes(const RenderSettings& settings, int max_pass = 32);

}  // namespace lp::render

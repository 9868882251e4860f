#include "engine/render/pass_schedule.hpp"

#include <algorithm>

#include "engine/render/adaptive_allocation.hpp"

namespace lp::render {

std::vector<int> pass_schedule(int spp, int max_pass) {
  std::vector<int> passes;
  int done = 0, next = 1;
  while (done < spp) {
    const int pass = std::min(next, spp - done);
    passes.push_back(pass);
    done += pass;
    if (passes.size() > 1) next = std::min(2 * next, max_pass);
  }
  return passes;
}

std::vector<RenderPass> render_passes(const RenderSettings& settings, int max_pass) {
  const bool adaptive = settings.sampling == SamplingMode::Adaptive;
  const int uniform = adaptive ? adaptive_warmup_spp(settings.spp) : settings.spp;
  std::vector<RenderPass> passes;
  for (const int spp : pass_schedule(uniform, max_pass)) passes.push_back({spp, false});
  if (uniform < settings.spp)
    for (const int spp : pass_schedule(settings.spp - uniform, max_pass)) passes.push_back({spp, true});
  return passes;
}

}  // namespace lp::render

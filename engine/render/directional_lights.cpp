#include "engine/render/directional_lights.hpp"

#include "engine/mediancut/median_cut.hpp"

namespace lp::render {

std::vector<DirectionalLight> median_cut_lights(const EnvLight& env, int count) {
  MedianCutParams params;
  params.count = count;
  params.validate(env.map().image().pixel_count(), "lighting.lights");
  if (env.dark()) return {};  // nothing to cut
  const auto cut = median_cut_cached(env.map(), params);
  std::vector<DirectionalLight> out;
  out.reserve(cut->lights.size());
  for (const MedianCutLight& l : cut->lights) {
    const Rgb power{float(l.power[0]), float(l.power[1]), float(l.power[2])};
    out.push_back({normalize(env.to_world(l.direction)), power * env.intensity()});
  }
  return out;
}

}  // namespace lp::render

#include "engine/render/directional_lights.hpp"

#include "engine/core/error.hpp"
#include "engine/mediancut/median_cut.hpp"

namespace lp::render {

std::vector<DirectionalLight> median_cut_lights(const EnvLight& env, int count) {
  if (count < 1 || int64_t(count) > int64_t(env.map().width()) * env.map().height())
    throw Error(ErrorKind::InvalidArgument, "lighting: lights must be between 1 and the map's pixel count");
  if (env.dark()) return {};  // nothing to cut
  MedianCutParams params;
  params.count = count;
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

#pragma once
// The environment map replaced by N directional (delta) lights from median cut (engine/mediancut):
// light i has direction d_i and a power P_i (the integral of the radiance over its region's solid
// angle), so a surface of normal n receives the irradiance E(n) = sum_i P_i max(0, n . d_i).
#include <vector>

#include "engine/render/env_light.hpp"

namespace lp::render {

struct DirectionalLight {
  Vec3 direction;  // world, unit, towards the light
  Rgb power;       // P_i above (median cut's power of the region) times the lighting intensity
};

// `count` lights from median cut of the map (engine/mediancut, cached per map), rotated and scaled like
// `env`. None for a black map. Throws lp::Error(InvalidArgument) if count < 1 or exceeds the map's pixels.
std::vector<DirectionalLight> median_cut_lights(const EnvLight& env, int count);

}  // namespace lp::render

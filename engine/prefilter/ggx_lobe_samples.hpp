#pragma once
// The GGX lobe of the split-sum prefilter (Karis 2013) under its assumption N = V = R: half vectors h
// drawn from D(h) (n.h), reflected into l = 2 (n.h) h - n and weighted by n.l, so that the weighted mean
// of the radiance along l converges to the lobe's convolution of the map. The density of l is D(h) / 4.
// One set of scrambled Sobol points (as the renderer's sample sets) in the lobe's own frame serves every
// direction, so the result varies smoothly from texel to texel.
#include <vector>

#include "engine/core/vec3.hpp"

namespace lp {

struct LobeSample {
  Vec3 direction;    // in the lobe's frame: z is the lobe's axis
  float weight = 0;  // n.l, above 0 (samples below the horizon are left out)
  float solid_angle =
      0;  // 1 / (count pdf): the solid angle the sample stands for (Krivanek and Colbert 2008)
};

// `count` samples drawn for a lobe of perceptual `roughness` (alpha = roughness^2), less those below
// the horizon.
std::vector<LobeSample> ggx_lobe_samples(double roughness, int count);

// The smallest solid angle one of `count` samples stands for: at the lobe's peak, where the density of
// l is D(n) / 4 = 1 / (4 pi alpha^2).
double smallest_sample_solid_angle(double roughness, int count);

}  // namespace lp

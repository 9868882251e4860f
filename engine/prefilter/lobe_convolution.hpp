#pragma once
// One level of a prefiltered chain as a function of direction: the GGX lobe of its roughness turned to
// the direction n (N = V = R), each sample read from the source at the level of the solid angle it
// stands for, and the radiance weighted by n.l: sum L(l) n.l / sum n.l (Karis 2013).
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/prefilter/prefilter_source.hpp"

namespace lp {

class LobeConvolution {
 public:
  // `source` must outlive the convolution.
  LobeConvolution(const PrefilterSource& source, double roughness, int samples);

  Rgb radiance(Vec3 n) const;

 private:
  struct Tap {
    Vec3 direction;  // in the lobe's frame
    float weight;    // n.l over the sum of n.l
    float lod;
  };
  const PrefilterSource& source_;
  std::vector<Tap> taps_;
};

}  // namespace lp

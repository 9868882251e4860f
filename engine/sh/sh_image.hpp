#pragma once
// A lat-long picture of an SH reconstruction, for showing beside the map it came from.
#include "engine/image/image.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp {

// The reconstruction sum_lm c_lm Y_lm at every pixel centre of a width x height lat-long image.
Image sh_reconstruction_image(const ShCoefficients& c, int width, int height);

}  // namespace lp

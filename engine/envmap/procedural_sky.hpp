#pragma once
// A simple analytic sky with a sun, so the server has a default map without any files.
#include "engine/image/image.hpp"

namespace lp {

// Blue sky graded to a bright horizon, a grey-brown ground, and a sun disc of 1.5 degrees radius at
// 35 degrees elevation with a radiance of about 2000 times the sky.
Image make_procedural_sky(int width = 1024, int height = 512);

}  // namespace lp

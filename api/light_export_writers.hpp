#pragma once
// The writers behind export_lights (api/light_export.hpp), one per format.
#include <string>

#include "api/light_export.hpp"

namespace lp::api {

// An RGB irradiance as a colour of largest channel 1 and a strength (that largest channel): what tools
// whose light colours stay within [0, 1] take. Black is white of strength 0.
struct ColorStrength {
  Power color{};
  double strength = 0;
};
ColorStrength color_strength(const Power& irradiance);

std::string mitsuba_lights(const LightSet& set, MitsubaFrame frame);
std::string blender_lights(const LightSet& set);
std::string usd_lights(const LightSet& set);
std::string gltf_lights(const LightSet& set);

}  // namespace lp::api

#include "engine/sun/sun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/constants.hpp"

namespace lp {

void set_sun_power(Sun& sun, const Power& power, double map_luminance) {
  sun.power = power;
  const double facing = (1 + std::cos(sun.angular_radius)) / 2;
  for (int c = 0; c < 3; ++c) {
    sun.color[c] = power[c] / sun.solid_angle;
    sun.irradiance[c] = power[c] * facing;
  }
  sun.share = map_luminance > 0 ? power_luminance(power, kSunLuminance) / map_luminance : 0;
  const double sky = power_luminance(sun.fill, kSunLuminance);
  sun.contrast =
      sky > 0 ? power_luminance(sun.color, kSunLuminance) / sky : std::numeric_limits<double>::infinity();
}

double cone_solid_angle(double radius) {
  const double s = std::sin(radius / 2);
  return 4 * kPi * s * s;
}

double cone_radius(double solid_angle) {
  return 2 * std::asin(std::min(1.0, std::sqrt(solid_angle / (4 * kPi))));
}

}  // namespace lp

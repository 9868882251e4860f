#pragma once
// Maps with a sun of known direction and power, for the tests and the benchmark of sun extraction: a
// smooth analytic sky (blue, brightening to the horizon, over a dim ground) and a disc added to any image.
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "engine/envmap/latlong.hpp"
#include "engine/image/image.hpp"
#include "engine/sun/cone_pixels.hpp"

namespace lp::test {

// A smooth sky without a compact emitter.
inline Rgb smooth_sky(Vec3 d) {
  if (d.z < 0) return Rgb{0.25f, 0.2f, 0.15f} * (1 + 0.5f * d.z);
  const float horizon = 1 - d.z;
  return Rgb{0.3f, 0.45f, 0.8f} + Rgb{0.5f, 0.45f, 0.3f} * (horizon * horizon);
}

// A lat-long image of width x width / 2 of f at the pixel centres.
inline Image latlong_image(int width, const std::function<Rgb(Vec3)>& f) {
  Image image(width, width / 2);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Direction d = pixel_centre_direction(x, y, image.width(), image.height());
      image.set(x, y, f(Vec3{float(d[0]), float(d[1]), float(d[2])}));
    }
  return image;
}

// A sun added to an image: `radiance` on every pixel whose centre lies within `radius` of `axis`.
struct AddedSun {
  Direction axis{};
  double radius = 0;              // radians
  std::array<double, 3> power{};  // radiance times the exact solid angle of those pixels
};

inline AddedSun add_sun(Image& image, double theta_deg, double phi_deg, double radius_deg, Rgb radiance) {
  const double deg = std::numbers::pi / 180, theta = theta_deg * deg, phi = phi_deg * deg;
  AddedSun sun{{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)},
               radius_deg * deg,
               {}};
  const int w = image.width(), h = image.height();
  for (int y = 0; y < h; ++y) {
    const double omega = latlong::pixel_solid_angle(y, w, h);
    for (int x = 0; x < w; ++x) {
      const Direction d = pixel_centre_direction(x, y, w, h);
      if (angle_between(d, sun.axis) > sun.radius) continue;
      image.set(x, y, image.at(x, y) + radiance);
      for (int c = 0; c < 3; ++c) sun.power[c] += radiance[c] * omega;
    }
  }
  return sun;
}

// The smooth sky at 512 x 256 with a sun 2 degrees across, 45 degrees up, of radiance 20000 (its
// pixels' power 17 a channel, the sky's above the horizon 2.9 in red): glass and glossy surfaces show it
// as fireflies, rare samples of up to 20000 beside a sky of about 1 (adaptive sampling's tests and
// benchmark).
inline Image firefly_sky() {
  Image image = latlong_image(512, smooth_sky);
  add_sun(image, 45, 0, 1, Rgb{2e4f, 2e4f, 2e4f});
  return image;
}

}  // namespace lp::test

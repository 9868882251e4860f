#include "engine/sun/sun_detection.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/sun/sun_core.hpp"
#include "engine/sun/sun_disc.hpp"

namespace lp {
namespace {

// The angle a pixel spans at most: its height, or its width at the equator.
double pixel_angle(int width, int height) {
  return std::max(kPi / height, 2 * kPi / width);
}

// The core's energy centroid (luminance * solid angle) and the angle of its farthest pixel centre.
struct CoreShape {
  Direction axis;
  double extent = 0;
};

CoreShape core_shape(const Image& image, const SunCore& core) {
  const int w = image.width(), h = image.height();
  Direction sum{};
  for (const PixelPos& p : core.pixels) {
    const double weight =
        double(luminance(image.at(p.x, p.y), kSunLuminance)) * latlong::pixel_solid_angle(p.y, w, h);
    const Direction d = pixel_centre_direction(p.x, p.y, w, h);
    for (int c = 0; c < 3; ++c) sum[c] += weight * d[c];
  }
  const double norm = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  CoreShape shape{{sum[0] / norm, sum[1] / norm, sum[2] / norm}, 0};
  for (const PixelPos& p : core.pixels)
    shape.extent = std::max(shape.extent, angle_between(shape.axis, pixel_centre_direction(p.x, p.y, w, h)));
  return shape;
}

Sun sun_of(const Image& image, const SunCore& core, PixelPos peak) {
  const CoreShape shape = core_shape(image, core);
  Sun sun;
  sun.axis = shape.axis;
  sun.direction = normalize(Vec3{float(shape.axis[0]), float(shape.axis[1]), float(shape.axis[2])});
  const latlong::Uv uv = latlong::uv(sun.direction);
  sun.pixel = {latlong::pixel_x(uv.u, image.width()), latlong::pixel_y(uv.v, image.height())};
  sun.peak = peak;
  sun.core_pixels = int64_t(core.pixels.size());
  sun.solid_angle = core.solid_angle;
  sun.angular_radius = cone_radius(core.solid_angle);
  sun.removed_radius = shape.extent + 1.5 * pixel_angle(image.width(), image.height());
  return sun;
}

// The fill and the power the sun would take: the disc's power above the ring's mean radiance.
void measure_disc(const Image& image, Sun& sun, double map_luminance) {
  const double ring_width = std::max(2 * pixel_angle(image.width(), image.height()), sun.removed_radius / 2);
  const DiscSums sums =
      sum_disc_and_ring(image, sun.axis, sun.removed_radius, sun.removed_radius + ring_width);
  sun.fill = sums.ring_mean();
  sun.removed_pixels = sums.disc_pixels;
  Power power{};
  for (int c = 0; c < 3; ++c) power[c] = sums.disc[c] - sun.fill[c] * sums.disc_solid_angle;
  set_sun_power(sun, power, map_luminance);
}

}  // namespace

SunDetection detect_sun(const Image& image, const SummedAreaTable& weight, const SunParams& params) {
  params.validate();
  const double max_radius = params.max_radius_deg * kPi / 180;
  const double map_luminance = weight.total();
  if (!(map_luminance > 0)) return {std::nullopt, "the map is black"};

  const int window = int(std::ceil(2 * max_radius / (kPi / image.height())));
  const PixelPos peak = brightest_spot(image, weight, kSunLuminance, std::min(window, image.height()));
  const float level = float(params.threshold) * luminance(image.at(peak.x, peak.y), kSunLuminance);
  const SunCore core = grow_sun_core(image, kSunLuminance, peak, level, cone_solid_angle(max_radius));
  if (!core.complete)
    return {std::nullopt, fmt::format("no compact emitter: the pixels around the brightest spot, pixel ({}, "
                                      "{}), of at least {} of its luminance spread over more than a cone "
                                      "of max_radius_deg {}",
                                      peak.x, peak.y, params.threshold, params.max_radius_deg)};
  Sun sun = sun_of(image, core, peak);
  measure_disc(image, sun, map_luminance);
  if (!(sun.share >= params.min_share) || !(sun.share > 0))
    return {
        std::nullopt,
        fmt::format("the brightest compact emitter, at pixel ({}, {}), carries {:.3g} of the map's power, "
                    "under min_share {}",
                    sun.pixel.x, sun.pixel.y, sun.share, params.min_share)};
  return {sun, ""};
}

}  // namespace lp

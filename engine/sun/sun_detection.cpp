#include "engine/sun/sun_detection.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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

// The luminance of the brightest pixel whose centre lies outside the sun's removed disc, at most:
// `candidates` are the map's brightest pixels, brightest first; if all lie inside, the last bounds it.
float brightest_elsewhere(const Image& image, const Sun& sun, const std::vector<PixelPos>& candidates) {
  for (const PixelPos& p : candidates)
    if (angle_between(sun.axis, pixel_centre_direction(p.x, p.y, image.width(), image.height())) >
        sun.removed_radius)
      return luminance(image.at(p.x, p.y), kSunLuminance);
  return candidates.empty() ? 0.0f
                            : luminance(image.at(candidates.back().x, candidates.back().y), kSunLuminance);
}

// The candidate at `peak` as a sun, or why it is none.
SunDetection try_candidate(const Image& image, PixelPos peak, const SunParams& params, double map_luminance,
                           const std::vector<PixelPos>& candidates, std::vector<PixelPos>& core_pixels) {
  const double max_radius = params.max_radius_deg * kPi / 180;
  const float level = float(params.threshold) * luminance(image.at(peak.x, peak.y), kSunLuminance);
  SunCore core = grow_sun_core(image, kSunLuminance, peak, level, cone_solid_angle(max_radius));
  core_pixels = core.pixels;
  if (!core.complete)
    return {std::nullopt, fmt::format("not compact: the pixels of at least {} of its luminance spread over "
                                      "more than a cone of max_radius_deg {}",
                                      params.threshold, params.max_radius_deg)};
  Sun sun = sun_of(image, core, peak);
  measure_disc(image, sun, map_luminance);
  if (!(sun.contrast >= params.min_contrast))
    return {std::nullopt, fmt::format("{:.3g} times as bright as the sky around it, under min_contrast {}",
                                      sun.contrast, params.min_contrast)};
  if (!(sun.share >= params.min_share) || !(sun.share > 0))
    return {std::nullopt, fmt::format("carries {:.3g} of the map's power, under min_share {}", sun.share,
                                      params.min_share)};
  const float peak_luminance = luminance(image.at(peak.x, peak.y), kSunLuminance);
  const float elsewhere = brightest_elsewhere(image, sun, candidates);
  if (!(peak_luminance >= kSunPeakOverElsewhere * elsewhere))
    return {std::nullopt, fmt::format("not the one brightest thing: a pixel elsewhere has {:.3g} of its "
                                      "luminance (a sun has over {} times anything else's)",
                                      elsewhere / peak_luminance, kSunPeakOverElsewhere)};
  return {sun, ""};
}

}  // namespace

SunDetection detect_sun(const Image& image, const SummedAreaTable& weight, const SunParams& params) {
  params.validate();
  const double map_luminance = weight.total();
  if (!(map_luminance > 0)) return {std::nullopt, "the map is black"};

  const int w = image.width();
  std::vector<bool> tried(size_t(w) * size_t(image.height()), false);
  std::string first_reason;
  int tries = 0;
  const std::vector<PixelPos> candidates = brightest_pixels(image, kSunLuminance, kSunCandidatePixels);
  for (const PixelPos& peak : candidates) {
    if (tried[size_t(peak.y) * size_t(w) + size_t(peak.x)]) continue;
    std::vector<PixelPos> core;
    SunDetection found = try_candidate(image, peak, params, map_luminance, candidates, core);
    if (found.sun) return found;
    for (const PixelPos& p : core) tried[size_t(p.y) * size_t(w) + size_t(p.x)] = true;
    if (first_reason.empty())
      first_reason = fmt::format("the brightest spot, pixel ({}, {}), is {}", peak.x, peak.y, found.reason);
    if (++tries == kSunCandidates) break;
  }
  return {
      std::nullopt,
      fmt::format(
          "{}{}", first_reason,
          tries > 1 ? fmt::format(" (and none of the next {} brightest spots is a sun)", tries - 1) : "")};
}

int64_t sun_detection_scratch_bytes(int64_t width, int64_t height) {
  return width * height / 8 + kSunCandidatePixels * 16;
}

}  // namespace lp

#include "engine/envmap/procedural_sky.hpp"

#include <cmath>

#include "engine/envmap/latlong.hpp"

namespace lp {
namespace {

constexpr float kSunElevationDeg = 35.0f, kSunAzimuthDeg = 60.0f, kSunRadiusDeg = 1.5f;

Rgb sky_radiance(Vec3 d, Vec3 sun) {
  const float deg = kPiF / 180.0f;
  if (dot(d, sun) >= std::cos(kSunRadiusDeg * deg)) return {2000.0f, 1900.0f, 1700.0f};
  if (d.z < 0)
    return Rgb{0.25f, 0.22f, 0.18f} * (0.6f + 0.4f * (1.0f + d.z));  // ground, darker straight down
  const float horizon = std::pow(1.0f - d.z, 4.0f);
  const float glow = std::pow(std::max(0.0f, dot(d, sun)), 8.0f);
  return Rgb{0.25f, 0.45f, 0.95f} * (1.0f - horizon) + Rgb{0.9f, 0.9f, 1.0f} * horizon +
         Rgb{1.5f, 1.2f, 0.8f} * glow;
}

}  // namespace

Image make_procedural_sky(int width, int height) {
  const float deg = kPiF / 180.0f;
  const Vec3 sun = latlong::direction_from_angles((90.0f - kSunElevationDeg) * deg, kSunAzimuthDeg * deg);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const latlong::Uv uv{(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)};
      image.set(x, y, sky_radiance(latlong::direction(uv), sun));
    }
  return image;
}

}  // namespace lp

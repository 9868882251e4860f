#pragma once
// Ray cones (Akenine-Moller et al., "Texture Level of Detail Strategies for Real-Time Ray Tracing",
// Ray Tracing Gems ch. 20, 2019, and "Improved Shader and Texture Level of Detail Using Ray Cones",
// JCGT 10(1), 2021) give each path vertex a footprint from which its texture level follows.
//
// Why cones rather than ray differentials: a cone is two floats per path and needs no derivatives of
// the BSDF sampling, and it still widens with distance, obliquity, curvature and roughness, which is
// what picks the level. The cone starts at the pinhole with the spread of one sample's share of a pixel
// (sample_spread); its width
// at a hit is width + spread * t; there a texture sees the cone's cross-section drawn out on the
// surface, an ellipse as wide as the cone across the ray and width / |cos| long along it, which the
// triangle's uv gradients turn into texture coordinates (texture_footprint.hpp filters over it).
// A bounce widens the spread by the surface curvature (a mirror of curvature k turns a beam of width w
// by k w, and reflection doubles it) and by the lobe: the sampled direction's pdf stands for a solid
// angle 1 / pdf, the cone of that solid angle has spread 2 sqrt(1 / (pi pdf)); delta lobes add nothing.
#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/frame.hpp"
#include "engine/core/vec3.hpp"

namespace lp::render {

// The spread a camera ray's cone starts with: the pixel's angle shared among its `spp` samples, each
// of which filters over 1 / sqrt(spp) of it (never less than an eighth), as pbrt-v4 scales its camera
// ray differentials. The samples already cover the pixel: filtering each over all of it would blur
// textures, the map and its sun twice.
inline float sample_spread(float pixel_spread, int spp) {
  return pixel_spread * std::max(0.125f, 1.0f / std::sqrt(float(std::max(spp, 1))));
}

// Two perpendicular diameters of the ellipse a cone covers on a surface, in the surface's plane.
struct SurfaceFootprint {
  Vec3 across;  // perpendicular to the ray: the cone's width
  Vec3 along;   // the ray's direction projected on the surface: the width / |cos|
};

struct RayCone {
  float width = 0;   // at the current origin
  float spread = 0;  // full angle, radians

  // The camera's cone: no width at the pinhole, one pixel's angle.
  static RayCone from_pixel(float pixel_spread) { return {0.0f, pixel_spread}; }

  void advance(float t) { width += spread * t; }

  // The width the cone covers on a surface met at `cos_incidence` (cosine between ray and normal).
  float surface_width(float cos_incidence) const {
    return std::abs(width) / std::max(std::abs(cos_incidence), kMinCos);
  }

  // The footprint on a surface of unit normal `normal` met by a ray of unit `direction`. Facing the
  // surface, the two diameters are equal and their directions arbitrary.
  SurfaceFootprint surface_footprint(Vec3 direction, Vec3 normal) const {
    const float cos_incidence = dot(direction, normal);
    const Vec3 projected = direction - normal * cos_incidence;
    const Vec3 along =
        dot(projected, projected) > 1e-12f ? normalize(projected) : Frame::from_normal(normal).s;
    return {cross(normal, along) * std::abs(width), along * surface_width(cos_incidence)};
  }

  void bounce(float curvature, float cos_incidence, bool delta, float pdf) {
    spread += 2.0f * curvature * surface_width(cos_incidence);
    if (!delta && pdf > 0) spread += 2.0f * std::sqrt(1.0f / (kPiF * pdf));
    spread = std::min(spread, kPiF);
  }

  static constexpr float kMinCos = 1e-3f;
};

}  // namespace lp::render

#pragma once
// Scattering at a surface, in the local shading frame (z = normal; both directions point away from the
// surface). Every BSDF samples, evaluates and gives a pdf, and the three agree: for a non-delta sample,
// weight == eval(wo, wi) / pdf(wo, wi). Radiance transport: a camera path carries radiance, so a
// transmission scales by 1 / eta^2 (radiance is compressed entering a denser medium).
#include <optional>

#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"

namespace lp::render {

struct BsdfSample {
  Vec3 wi;
  Rgb weight;          // f(wo, wi) |cos wi| / pdf
  float pdf = 0;       // solid-angle pdf; for a delta lobe, the probability of having chosen it
  float eta = 1;       // eta_t / eta_i when the sample crosses the surface, else 1
  bool delta = false;  // a specular lobe: eval() and pdf() do not contain it
};

class Bsdf {
 public:
  virtual ~Bsdf() = default;

  // f(wo, wi) |cos wi| of the non-delta lobes.
  virtual Rgb eval(Vec3 wo, Vec3 wi) const = 0;
  // Solid-angle density with which sample() returns wi among its non-delta lobes.
  virtual float pdf(Vec3 wo, Vec3 wi) const = 0;
  // u_lobe chooses among lobes, u the direction within one.
  virtual std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const = 0;

  // False if every lobe is delta (light sampling is then useless).
  virtual bool has_non_delta_lobe() const = 0;
  // True: a reflector that looks the same from both sides (the caller flips the normal towards wo).
  // False: the BSDF distinguishes the outside (z > 0) from the inside (a dielectric).
  virtual bool two_sided() const { return true; }
};

// The non-delta sample of `bsdf` in direction wi, weighted eval / pdf; nullopt when wi is below the
// surface or its pdf is 0.
std::optional<BsdfSample> weighted_sample(const Bsdf& bsdf, Vec3 wo, Vec3 wi);

}  // namespace lp::render

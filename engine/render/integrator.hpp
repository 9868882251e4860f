#pragma once
// Unidirectional path tracing with next-event estimation. The light is the environment map, sampled
// per the lighting mode:
//   envmap:  importance sampling of the map (MIS-compensated, env_light.hpp), combined with BSDF
//            sampling by MIS (power heuristic, exponent 1.5); with a sun taken out of the map
//            (sun_light.hpp), the sun is sampled too at every bounce, its own MIS against BSDF
//            sampling, and the map is its residual;
//   uniform: uniform sphere sampling, with MIS;
//   bsdf:    no light sampling, paths count the map when they escape;
//   median_cut / median_cut_all: directional lights from median cut, one picked per shading point
//            (pdf 1/n) or all of them. The map itself then lights nothing: it is only seen by the
//            camera and through chains of delta (mirror, glass) bounces.
// A path that refracts into a model's closed volume (KHR_materials_volume) is attenuated by
// Beer-Lambert, exp(-sigma t), along every segment until it refracts out again.
// Russian roulette from the fifth bounce on; `max_depth` bounces at most.
// Camera rays that escape see the background (scene_desc.hpp, Background); one that meets a shadow
// catcher sees the background darkened by the catcher's shadow (shadow_catcher below). Each path also
// gives the auxiliary passes of its first hit (scene_desc.hpp, AuxPass).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "engine/bsdf/bsdf.hpp"
#include "engine/core/frame.hpp"
#include "engine/render/directional_lights.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/model_bsdf.hpp"
#include "engine/render/ray_cone.hpp"
#include "engine/render/sun_light.hpp"

namespace lp::render {

struct IntegratorConfig {
  LightingMode mode = LightingMode::EnvMap;
  int max_depth = 8;
  bool env_visible = true;  // camera rays that escape see the map (else black)
  float pixel_spread = 0;   // a camera ray cone's starting angle (radians; sample_spread)
  bool mipmaps = true;      // texture levels from ray cones (else level 0)
  bool normal_maps = true;
  float texture_anisotropy = kMaxTextureAnisotropy;  // RenderSettings::texture_anisotropy
  Background background;
  std::optional<float> clamp;  // RenderSettings::clamp
  std::vector<bool> catchers;  // by object: whether it is a shadow catcher
};

// What one camera sample gives: its radiance and the auxiliary passes of its first hit.
struct PathSample {
  Rgb color;
  float alpha = 0;  // coverage, or a shadow catcher's shadow opacity
  Rgb albedo;
  Vec3 normal;
  float depth = 0;   // the distance to the first visible hit, when `hit`
  bool hit = false;  // the camera ray met a visible surface
};

class Integrator {
 public:
  // `sun`: the sun taken out of the map, or null.
  Integrator(const EmbreeScene& scene, const std::vector<std::unique_ptr<Bsdf>>& bsdfs, const EnvLight& env,
             const SunLight* sun, const std::vector<DirectionalLight>& lights,
             const IntegratorConfig& config);

  // Radiance along a camera ray, whose hit the caller traced (in packets, EmbreeScene::intersect_packet),
  // and the passes of its first hit. Adds the rays of the path to `rays`, the camera ray included.
  PathSample radiance(const Ray& camera_ray, const std::optional<SurfaceHit>& camera_hit,
                      PathSampler& sampler, uint64_t& rays) const;

 private:
  struct Shading {
    const SurfaceHit& hit;
    Frame frame;  // around the shading normal
    const Bsdf& bsdf;
    Vec3 wo;         // local
    Vec3 geometric;  // the geometric normal, on the side of wo for two-sided BSDFs
    Rgb emission;
    Rgb interior_absorption;  // of the volume a one-sided BSDF encloses (behind its normal)
  };
  // The BSDF, frame and emission at a hit; a model's BSDF is built in `model_bsdf`.
  Shading shade(const SurfaceHit& hit, Vec3 wo_world, const RayCone& cone, ModelBsdf& model_bsdf) const;
  // False for a direction on the other side of the geometric surface than the shading frame puts it,
  // which a two-sided BSDF must not reach through a perturbed shading normal (a reflection would leak
  // light through the surface, a transmission would not cross it).
  static bool same_side(const Shading& s, Vec3 direction) {
    if (!s.bsdf.two_sided()) return true;
    const bool through = dot(direction, s.frame.n) < 0;
    return (dot(direction, s.geometric) > 0) != through;
  }
  // `env_choice`: the probability that the last hit's light sample went to the map.
  Rgb escaped(const EnvPixel& pixel, float spread, int depth, bool delta_chain, bool last_delta,
              float bsdf_pdf, float env_choice) const;
  // The sun seen along an escaping ray, weighed as escaped() weighs the map.
  // `choice`: the probability that the last hit's light sample went to the sun.
  Rgb escaped_sun(Vec3 direction, int depth, bool last_delta, float bsdf_pdf, float choice) const;
  // What a camera ray that meets a shadow catcher sees: the background behind the catcher times the
  // fraction of the catcher's direct light its shadows leave, one light sample and one BSDF sample each
  // traced with and without their shadow ray, as OSPRay's shadow catcher does, plus the light the
  // objects send the catcher along the BSDF sample (reflections and bounce light, as Cycles' catcher
  // keeps them), which is indirect light and clamped as such. Its alpha is the shadow's opacity: over a
  // transparent background the colour is the reflected light alone, premultiplied, so compositing it
  // over any page adds the reflections and darkens by the shadow. Where nothing shadows the catcher the
  // two sums are the same numbers added in the same order, so the fraction is exactly 1.
  PathSample shadow_catcher(const Ray& ray, const SurfaceHit& hit, PathSampler& sampler,
                            uint64_t& rays) const;
  // `u_select` picks a median-cut light, or the sun (with probability `sun_choice`) over the map.
  // `unshadowed`, when given, also sums the contributions as if nothing occluded them.
  Rgb direct(const Shading& s, Point2 u_light, float u_select, float sun_choice, uint64_t& rays,
             Rgb* unshadowed = nullptr) const;
  Rgb direct_env(const Shading& s, const LightSample& light, float light_pdf, uint64_t& rays,
                 Rgb* unshadowed) const;
  Rgb direct_directional(const Shading& s, const DirectionalLight& light, uint64_t& rays,
                         Rgb* unshadowed) const;
  // An indirect contribution within the clamp.
  Rgb clamped(Rgb c) const;
  bool visible(const SurfaceHit& hit, Vec3 direction, uint64_t& rays) const;

  const EmbreeScene& scene_;
  const std::vector<std::unique_ptr<Bsdf>>& bsdfs_;
  const EnvLight& env_;
  const SunLight* sun_;
  const std::vector<DirectionalLight>& lights_;
  IntegratorConfig config_;
};

}  // namespace lp::render

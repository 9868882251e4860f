#include "engine/render/integrator.hpp"

#include <algorithm>
#include <cmath>

#include "engine/render/model_shading.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

// Russian roulette from the fifth bounce on, as Mitsuba 3 does by default. From the third it cut the
// paths that carry the glass sphere's caustics (a diffuse bounce, then two through the glass), and the
// squared error at equal samples was 1.7 times this on `materials` and 1.17 times on the glossy scene
// under city.exr, for 2 to 3% fewer rays (bench/README.md, "Russian roulette").
inline constexpr int kRouletteDepth = 5;

// The MIS weight of a sample drawn with pdf a against another strategy's pdf b: Veach's power heuristic,
// a^k / (a^k + b^k), with k = 1.5 rather than his usual 2. Between the balance heuristic (k = 1), for
// which a compensated light distribution is the optimal one (Karlik et al. 2019), and k = 2, which wins
// where one strategy alone is the better one; at equal samples it lowered the squared error on every
// scene and map measured (bench/README.md, "The MIS weight").
float mis_weight(float a, float b) {
  const float ak = a * std::sqrt(a), bk = b * std::sqrt(b);
  return ak + bk > 0 ? ak / (ak + bk) : 0.0f;
}

bool is_black(Rgb c) {
  return c.x <= 0 && c.y <= 0 && c.z <= 0;
}

// Beer-Lambert transmittance over a length t of a medium with absorption coefficient sigma.
Rgb transmittance(Rgb sigma, float t) {
  return {std::exp(-sigma.x * t), std::exp(-sigma.y * t), std::exp(-sigma.z * t)};
}

// Whether a camera ray that escapes sees the map: else it needs no lookup in it.
bool map_behind(const IntegratorConfig& config) {
  return config.background.mode == BackgroundMode::Map && config.env_visible;
}

}  // namespace

Integrator::Integrator(const EmbreeScene& scene, const std::vector<std::unique_ptr<Bsdf>>& bsdfs,
                       const EnvLight& env, const SunLight* sun, const std::vector<DirectionalLight>& lights,
                       const IntegratorConfig& config)
    : scene_(scene), bsdfs_(bsdfs), env_(env), sun_(sun), lights_(lights), config_(config) {}

PathSample Integrator::radiance(const Ray& camera_ray, const std::optional<SurfaceHit>& camera_hit,
                                PathSampler& sampler, uint64_t& rays) const {
  if (camera_hit && config_.catchers[camera_hit->object])
    return shadow_catcher(camera_ray, *camera_hit, sampler, rays);
  PathSample out;
  Rgb& result = out.color;
  Rgb beta{1, 1, 1};
  Ray ray = camera_ray;
  bool delta_chain = true, last_delta = true, albedo_taken = false;
  float bsdf_pdf = 0, eta_scale = 1;
  float sun_choice = 0;  // at the last hit, the probability that its light sample went to the sun
  const bool lit_by_map =
      config_.mode != LightingMode::MedianCut && config_.mode != LightingMode::MedianCutAll;
  EnvPixel escape{};  // where a bounce ray lands in the map if it escapes, located while it is traced
  RayCone cone = RayCone::from_pixel(config_.pixel_spread);
  Rgb absorption{};  // of the volume the path is inside
  // Light reaching the first hit over another surface is indirect: what the path finds from its third
  // vertex on, and the light sampled at its second.
  const auto add = [&](Rgb c, bool indirect) { result += indirect ? clamped(c) : c; };
  for (int depth = 0;; ++depth) {
    ++rays;
    const std::optional<SurfaceHit> hit = depth == 0 ? camera_hit : scene_.intersect(ray);
    if (!hit) {
      if (depth == 0 && map_behind(config_)) escape = env_.locate(ray.direction);
      add(beta * escaped(escape, cone.spread, depth, delta_chain, last_delta, bsdf_pdf, 1 - sun_choice),
          depth >= 2);
      if (sun_) add(beta * escaped_sun(ray.direction, depth, last_delta, bsdf_pdf, sun_choice), depth >= 2);
      break;
    }
    cone.advance(hit->t);
    if (!is_black(absorption)) beta *= transmittance(absorption, hit->t);
    ModelBsdf model_bsdf;
    const Shading shading = shade(*hit, -ray.direction, cone, model_bsdf);
    if (depth == 0) {
      out.alpha = 1;
      out.hit = true;
      out.depth = hit->t;
      out.normal = shading.frame.n;
    }
    add(beta * shading.emission, depth >= 2);
    if (depth >= config_.max_depth) break;
    const Bsdf& bsdf = shading.bsdf;

    // A fixed number of dimensions per bounce, whatever the branches, keeps the sequences aligned.
    const Point2 u_light = sampler.get_2d();
    const Point2 u_choice = sampler.get_2d();  // x: which light, y: which BSDF lobe
    const Point2 u_bsdf = sampler.get_2d();
    const float u_roulette = sampler.get_1d();

    sun_choice = sun_ ? sun_->selection(shading.frame.n) : 0;
    if (bsdf.has_non_delta_lobe())
      add(beta * direct(shading, u_light, u_choice.x, sun_choice, rays), depth >= 1);

    const std::optional<BsdfSample> s = bsdf.sample(shading.wo, u_choice.y, u_bsdf);
    if (!albedo_taken && bsdf.has_non_delta_lobe()) {
      out.albedo = s ? beta * s->weight : Rgb{};
      albedo_taken = true;
    }
    if (!s || is_black(s->weight)) break;
    beta *= s->weight;
    last_delta = s->delta;
    delta_chain = delta_chain && s->delta;
    bsdf_pdf = s->pdf;
    eta_scale *= s->eta * s->eta;
    if (depth + 1 >= kRouletteDepth) {
      const float q = std::min(1.0f, max_component(beta) * eta_scale);
      if (u_roulette >= q) break;
      beta = beta / q;
    }
    const Vec3 wi = normalize(shading.frame.to_world(s->wi));
    if (!same_side(shading, wi)) break;
    if (!bsdf.two_sided() && (s->wi.z < 0) != (shading.wo.z < 0))
      absorption = s->wi.z < 0 ? shading.interior_absorption : Rgb{};
    cone.bounce(hit->curvature, dot(ray.direction, hit->normal), s->delta, s->pdf);
    ray = {EmbreeScene::offset_origin(*hit, wi), wi};
    if (lit_by_map || delta_chain) escape = env_.locate(wi);
  }
  return out;
}

PathSample Integrator::shadow_catcher(const Ray& ray, const SurfaceHit& hit, PathSampler& sampler,
                                      uint64_t& rays) const {
  ++rays;
  const RayCone camera_cone = RayCone::from_pixel(config_.pixel_spread);
  RayCone cone = camera_cone;
  cone.advance(hit.t);
  ModelBsdf model_bsdf;
  const Shading s = shade(hit, -ray.direction, cone, model_bsdf);
  const Point2 u_light = sampler.get_2d();
  const Point2 u_choice = sampler.get_2d();
  const Point2 u_bsdf = sampler.get_2d();
  const float sun_choice = sun_ ? sun_->selection(s.frame.n) : 0;
  Rgb unshadowed{}, reflected{};
  Rgb lit =
      s.bsdf.has_non_delta_lobe() ? direct(s, u_light, u_choice.x, sun_choice, rays, &unshadowed) : Rgb{};
  if (const auto b = s.bsdf.sample(s.wo, u_choice.y, u_bsdf); b && !is_black(b->weight)) {
    const Vec3 wi = normalize(s.frame.to_world(b->wi));
    if (same_side(s, wi)) {
      Rgb c = b->weight * escaped(env_.locate(wi), cone.spread, 1, false, b->delta, b->pdf, 1 - sun_choice);
      if (sun_) c += b->weight * escaped_sun(wi, 1, b->delta, b->pdf, sun_choice);
      unshadowed += c;
      ++rays;
      const Ray next{EmbreeScene::offset_origin(hit, wi), wi};
      if (const std::optional<SurfaceHit> object = scene_.intersect(next); !object)
        lit += c;
      else if (!config_.catchers[object->object])
        reflected = clamped(b->weight * radiance(next, object, sampler, rays).color);
    }
  }
  const float open = unshadowed.x + unshadowed.y + unshadowed.z;
  const float left = open > 0 ? std::clamp((lit.x + lit.y + lit.z) / open, 0.0f, 1.0f) : 1.0f;
  Rgb behind = escaped(env_.locate(ray.direction), camera_cone.spread, 0, true, true, 0, 1);
  if (sun_) behind += escaped_sun(ray.direction, 0, true, 0, 0);
  PathSample out;
  out.color = behind * left + reflected;
  out.alpha = 1 - left;
  return out;
}

Rgb Integrator::clamped(Rgb c) const {
  if (!config_.clamp) return c;
  const float m = max_component(c);
  return m > *config_.clamp ? c * (*config_.clamp / m) : c;
}

Integrator::Shading Integrator::shade(const SurfaceHit& hit, Vec3 wo, const RayCone& cone,
                                      ModelBsdf& model_bsdf) const {
  Vec3 ns = hit.shading_normal;
  Rgb emission{}, absorption{};
  const Bsdf* bsdf = bsdfs_[hit.object].get();
  if (hit.material) {
    const TextureLookup lookup{cone.surface_footprint(wo, hit.normal), config_.mipmaps, config_.normal_maps,
                               config_.texture_anisotropy};
    const ModelSurface surface = model_surface(*hit.material, hit, lookup);
    bsdf = &model_bsdf.make(surface);
    ns = surface.shading_normal;
    emission = surface.emission;
    if (surface.lobes) absorption = surface.lobes->absorption;
  }
  const bool flip = bsdf->two_sided() && dot(wo, hit.normal) < 0;
  const Vec3 ng = flip ? -hit.normal : hit.normal;
  if (flip) ns = -ns;
  if (bsdf->two_sided() && ns != ng) ns = bend_shading_normal(ns, ng, wo);
  const Frame frame = Frame::from_normal(ns);
  model_bsdf.orient(frame, flip);
  return {hit, frame, *bsdf, frame.to_local(wo), ng, emission, absorption};
}

Rgb Integrator::escaped(const EnvPixel& pixel, float spread, int depth, bool delta_chain, bool last_delta,
                        float bsdf_pdf, float env_choice) const {
  if (depth == 0 && !map_behind(config_))
    return config_.background.mode == BackgroundMode::Color ? config_.background.color : Rgb{};
  // A camera ray or a ray leaving a delta lobe takes no part in MIS: it sees the map over its
  // footprint. Every other ray reads the importance grid, as the light samples it is weighed against do.
  const Rgb seen = last_delta
                       ? (config_.mipmaps ? env_.radiance_over(pixel, spread) : env_.radiance_sharp(pixel))
                       : env_.radiance(pixel);
  if (depth == 0) return seen;
  switch (config_.mode) {
    case LightingMode::Bsdf:
      return seen;
    case LightingMode::EnvMap:
      return last_delta ? seen : seen * mis_weight(bsdf_pdf, env_choice * env_.importance_pdf(pixel));
    case LightingMode::Uniform:
      return last_delta ? seen : seen * mis_weight(bsdf_pdf, kUniformSpherePdf);
    case LightingMode::MedianCut:
    case LightingMode::MedianCutAll:
      return delta_chain ? seen : Rgb{};
  }
  return {};
}

Rgb Integrator::escaped_sun(Vec3 direction, int depth, bool last_delta, float bsdf_pdf, float choice) const {
  if (!sun_->contains(direction)) return {};
  if (depth == 0)
    return config_.env_visible && config_.background.mode == BackgroundMode::Map ? sun_->radiance() : Rgb{};
  return last_delta ? sun_->radiance() : sun_->radiance() * mis_weight(bsdf_pdf, choice * sun_->pdf());
}

Rgb Integrator::direct(const Shading& s, Point2 u_light, float u_select, float sun_choice, uint64_t& rays,
                       Rgb* unshadowed) const {
  switch (config_.mode) {
    case LightingMode::EnvMap: {
      if (u_select < sun_choice)
        return direct_env(s, sun_->sample(u_light), sun_choice * sun_->pdf(), rays, unshadowed);
      const LightSample light = env_.sample_importance(u_light);
      return direct_env(s, light, (1 - sun_choice) * light.pdf, rays, unshadowed);
    }
    case LightingMode::Uniform:
      return direct_env(s, env_.sample_uniform(u_light), kUniformSpherePdf, rays, unshadowed);
    case LightingMode::Bsdf:
      return {};
    case LightingMode::MedianCut: {
      const size_t n = lights_.size();
      if (n == 0) return {};
      const size_t i = std::min(n - 1, size_t(u_select * float(n)));
      Rgb open{};
      const Rgb c = direct_directional(s, lights_[i], rays, &open) * float(n);
      if (unshadowed) *unshadowed += open * float(n);
      return c;
    }
    case LightingMode::MedianCutAll: {
      Rgb sum{};
      for (const DirectionalLight& light : lights_) sum += direct_directional(s, light, rays, unshadowed);
      return sum;
    }
  }
  return {};
}

Rgb Integrator::direct_env(const Shading& s, const LightSample& light, float light_pdf, uint64_t& rays,
                           Rgb* unshadowed) const {
  if (!(light_pdf > 0) || is_black(light.radiance) || !same_side(s, light.direction)) return {};
  const Vec3 wi = s.frame.to_local(light.direction);
  const Rgb f = s.bsdf.eval(s.wo, wi);
  if (is_black(f)) return {};
  const float weight = mis_weight(light_pdf, s.bsdf.pdf(s.wo, wi));
  const Rgb c = f * light.radiance * (weight / light_pdf);
  if (unshadowed) *unshadowed += c;
  return visible(s.hit, light.direction, rays) ? c : Rgb{};
}

Rgb Integrator::direct_directional(const Shading& s, const DirectionalLight& light, uint64_t& rays,
                                   Rgb* unshadowed) const {
  if (!same_side(s, light.direction)) return {};
  const Rgb f = s.bsdf.eval(s.wo, s.frame.to_local(light.direction));
  if (is_black(f)) return {};
  const Rgb c = f * light.power;
  if (unshadowed) *unshadowed += c;
  return visible(s.hit, light.direction, rays) ? c : Rgb{};
}

bool Integrator::visible(const SurfaceHit& hit, Vec3 direction, uint64_t& rays) const {
  ++rays;
  return !scene_.occluded({EmbreeScene::offset_origin(hit, direction), direction});
}

}  // namespace lp::render

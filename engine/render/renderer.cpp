#include "engine/render/renderer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define LP_HAVE_MXCSR 1
#endif

#include "engine/core/error.hpp"
#include "engine/render/adaptive_allocation.hpp"
#include "engine/render/aux_passes.hpp"
#include "engine/render/camera.hpp"
#include "engine/render/directional_lights.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/film.hpp"
#include "engine/render/integrator.hpp"
#include "engine/render/material_bsdf.hpp"
#include "engine/render/path_sampler.hpp"
#include "engine/render/scene_view.hpp"
#include "engine/render/sun_light.hpp"

namespace lp::render {
namespace {

inline constexpr int kTileSize = 16;
inline constexpr int kPacket = EmbreeScene::kPacket;

// The samples one pixel draws in a pass: n of them from index `first`.
struct SampleRun {
  uint32_t first = 0, n = 0;
};

std::vector<bool> shadow_catchers(const SceneDesc& scene) {
  std::vector<bool> out;
  for (const SceneObject& o : scene.objects) out.push_back(o.ground && o.ground->shadow_catcher);
  return out;
}

std::vector<std::unique_ptr<Bsdf>> make_bsdfs(const SceneDesc& scene) {
  std::vector<std::unique_ptr<Bsdf>> out;
  for (const SceneObject& o : scene.objects) out.push_back(make_bsdf(o.material));
  return out;
}

// Embree recommends flush-to-zero and denormals-are-zero; set per tile and restored, since the
// worker threads are shared with other code.
class FlushDenormals {
 public:
#ifdef LP_HAVE_MXCSR
  FlushDenormals() : saved_(_mm_getcsr()) {
    _mm_setcsr(saved_ | 0x8040u);
  }
  ~FlushDenormals() {
    _mm_setcsr(saved_);
  }

 private:
  unsigned saved_;
#endif
};

// Runs `render(tile)` for every tile in parallel, then `on_tile`; false if `cancel` became true (checked
// before each tile, so some were skipped).
template <class Render>
bool for_each_tile(int tiles, const std::atomic<bool>& cancel, const std::function<void()>& on_tile,
                   Render&& render) {
  std::atomic<bool> skipped{false};
  tbb::parallel_for(
      tbb::blocked_range<int>(0, tiles, 1),
      [&](const tbb::blocked_range<int>& range) {
        for (int t = range.begin(); t != range.end(); ++t) {
          if (cancel.load(std::memory_order_relaxed)) {
            skipped.store(true, std::memory_order_relaxed);
            continue;
          }
          render(t);
          if (on_tile) on_tile();
        }
      },
      tbb::simple_partitioner());
  return !skipped.load();
}

}  // namespace

struct Renderer::Impl {
  Impl(const SceneDesc& scene, const Lighting& lighting, const RenderSettings& s,
       std::shared_ptr<const EnvMap> envmap)
      : settings(s),
        camera(scene.camera, s.width, s.height),
        bsdfs(make_bsdfs(scene)),
        split(split_sun(std::move(envmap), lighting)),
        env(split.environment, lighting),
        sun(split.sun ? std::optional<SunLight>(SunLight(*split.sun, env, *split.environment))
                      : std::nullopt),
        lights(uses_lights(lighting.mode) ? median_cut_lights(env, lighting.lights)
                                          : std::vector<DirectionalLight>{}),
        geometry(scene, s.mesh_limits),
        integrator(
            geometry, bsdfs, env, sun ? &*sun : nullptr, lights,
            {lighting.mode, s.max_depth, lighting.visible, sample_spread(camera.pixel_spread(), s.spp),
             s.mipmaps, s.normal_maps, s.texture_anisotropy, s.background, s.clamp, shadow_catchers(scene)}),
        film(s.width, s.height, s.passes),
        tiles_x((s.width + kTileSize - 1) / kTileSize),
        tiles_y((s.height + kTileSize - 1) / kTileSize) {}

  static bool uses_lights(LightingMode m) {
    return m == LightingMode::MedianCut || m == LightingMode::MedianCutAll;
  }

  // Renders the samples of every pixel of the tile: pixel (x, y) draws `runs(x, y).n` samples from
  // index `runs(x, y).first`, and hands their sum and the sum of their squared channels to
  // `store(x, y, sum, squares, rays, aux)` (aux: the sums of the auxiliary channels). Camera rays are traced
  // kPacket at a time, filled in order from the samples of a run of kPacket pixels of a row: sample i of each
  // pixel that draws it, then sample i + 1, so a pass with the same counts everywhere traces one sample index
  // of the run per packet, and an adaptive pass, whose counts differ, still fills every packet but the run's
  // last. Which rays share a packet depends only on the tile and the counts, so a pass, a range of samples or
  // another thread count traces every ray alike. Each pixel adds its samples in index order.
  template <class Runs, class Store>
  void render_tile(int tile, Runs&& runs_of, Store&& store) {
    const FlushDenormals ftz;
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, settings.width), y1 = std::min(y0 + kTileSize, settings.height);
    uint64_t tile_rays = 0, tile_samples = 0;
    for (int y = y0; y < y1; ++y) {
      for (int xs = x0; xs < x1; xs += kPacket) {
        const int n = std::min(kPacket, x1 - xs);
        SampleRun runs[kPacket];
        uint32_t longest = 0;
        for (int k = 0; k < n; ++k) {
          runs[k] = runs_of(xs + k, y);
          longest = std::max(longest, runs[k].n);
          tile_samples += runs[k].n;
        }
        Rgb sums[kPacket] = {};
        float squares[kPacket] = {};
        float aux[kPacket][kMaxAuxChannels] = {};
        uint32_t pixel_rays[kPacket] = {};
        int lanes[kPacket], queued = 0;
        uint32_t indices[kPacket];
        const int aux_channels = settings.passes.channels();
        const auto flush = [&] {
          PathSample l[kPacket];
          uint64_t lane_rays[kPacket] = {};
          trace_packet(xs, y, {lanes, size_t(queued)}, indices, l, lane_rays);
          for (int a = 0; a < queued; ++a) {
            tile_rays += lane_rays[a];
            pixel_rays[lanes[a]] += uint32_t(lane_rays[a]);
            if (aux_channels > 0) add_aux(l[a], aux[lanes[a]]);
            const Rgb c = l[a].color;
            if (!finite(c)) continue;  // a numerical failure must not poison the image
            sums[lanes[a]] += c;
            squares[lanes[a]] += c.x * c.x + c.y * c.y + c.z * c.z;
          }
          queued = 0;
        };
        for (uint32_t i = 0; i < longest; ++i)
          for (int k = 0; k < n; ++k) {
            if (i >= runs[k].n) continue;
            indices[queued] = runs[k].first + i, lanes[queued++] = k;
            if (queued == kPacket) flush();
          }
        if (queued > 0) flush();
        for (int k = 0; k < n; ++k) store(xs + k, y, sums[k], squares[k], pixel_rays[k], aux[k]);
      }
    }
    samples.fetch_add(tile_samples, std::memory_order_relaxed);
    rays.fetch_add(tile_rays, std::memory_order_relaxed);
  }

  // Adds a sample's auxiliary values to a pixel's sums, unless one is not finite.
  void add_aux(const PathSample& sample, float* sums) const {
    float v[kMaxAuxChannels];
    const int n = settings.passes.channels();
    aux_values(sample, settings.passes, v);
    for (int c = 0; c < n; ++c)
      if (!std::isfinite(v[c])) return;
    for (int c = 0; c < n; ++c) sums[c] += v[c];
  }

  // Sample indices[a] of pixel (x + lanes[a], y) for each lane a, its radiance and passes into out[a];
  // a pixel may fill several lanes.
  void trace_packet(int x, int y, std::span<const int> lanes, const uint32_t* indices, PathSample* out,
                    uint64_t* lane_rays) const {
    std::optional<PathSampler> samplers[kPacket];
    Ray camera_rays[kPacket];
    std::optional<SurfaceHit> hits[kPacket];
    const size_t n = lanes.size();
    for (size_t a = 0; a < n; ++a) {
      const int px = x + lanes[a];
      const uint64_t pixel = uint64_t(y) * uint64_t(settings.width) + uint64_t(px);
      PathSampler& sampler = samplers[a].emplace(settings.seed, pixel, indices[a]);
      const Point2 jitter = sampler.get_2d();
      camera_rays[a] = camera.generate(float(px) + jitter.x, float(y) + jitter.y);
    }
    geometry.intersect_packet({camera_rays, n}, {hits, n});
    for (size_t a = 0; a < n; ++a)
      out[a] = integrator.radiance(camera_rays[a], hits[a], *samplers[a], lane_rays[a]);
  }

  // Renders every tile with the samples `runs(x, y)` of each pixel into the film's staging buffer.
  template <class Runs>
  bool render_into_film(const std::atomic<bool>& cancel, const std::function<void()>& on_tile,
                        const Runs& runs) {
    const auto store = [this](int x, int y, Rgb sum, float squares, uint32_t traced, const float* aux) {
      film.set_pass_sum(x, y, sum, squares, traced);
      if (!settings.passes.empty()) film.set_pass_aux(x, y, aux);
    };
    return for_each_tile(tiles_x * tiles_y, cancel, on_tile, [&](int t) { render_tile(t, runs, store); });
  }

  RenderSettings settings;
  PerspectiveCamera camera;
  std::vector<std::unique_ptr<Bsdf>> bsdfs;
  SunSplit split;
  EnvLight env;
  std::optional<SunLight> sun;
  std::vector<DirectionalLight> lights;
  EmbreeScene geometry;
  Integrator integrator;
  Film film;
  int tiles_x, tiles_y;
  std::atomic<uint64_t> samples{0}, rays{0};
  uint32_t adaptive_passes = 0;
};

Renderer::Renderer(const SceneDesc& scene, const Lighting& lighting, const RenderSettings& settings,
                   std::shared_ptr<const EnvMap> envmap) {
  scene.validate("scene");
  lighting.validate("lighting");
  settings.validate("settings");
  SceneDesc resolved = scene;
  if (needs_models(scene)) load_missing_models(resolved, settings.mesh_limits);
  resolve_grounds(resolved);
  resolved.camera = resolve_camera(resolved, float(settings.width) / float(settings.height));
  resolved.camera.validate("scene.camera");
  impl_ = std::make_unique<Impl>(resolved, lighting, settings, std::move(envmap));
}

Renderer::~Renderer() = default;

int Renderer::tile_count() const {
  return impl_->tiles_x * impl_->tiles_y;
}

bool Renderer::render_pass(int spp, const std::atomic<bool>& cancel, const std::function<void()>& on_tile) {
  if (spp < 1) throw Error(ErrorKind::InvalidArgument, "render_pass: spp must be >= 1");
  Film& film = impl_->film;
  const auto runs = [&film, spp](int x, int y) { return SampleRun{film.count(x, y), uint32_t(spp)}; };
  if (!impl_->render_into_film(cancel, on_tile, runs)) return false;
  film.merge_pass(spp);
  return true;
}

bool Renderer::render(const RenderPass& pass, const std::atomic<bool>& cancel,
                      const std::function<void()>& on_tile) {
  return pass.adaptive ? render_adaptive_pass(pass.spp, cancel, on_tile)
                       : render_pass(pass.spp, cancel, on_tile);
}

bool Renderer::render_adaptive_pass(int spp, const std::atomic<bool>& cancel,
                                    const std::function<void()>& on_tile) {
  if (spp < 1) throw Error(ErrorKind::InvalidArgument, "render_adaptive_pass: spp must be >= 1");
  Film& film = impl_->film;
  if (film.restored())
    throw Error(
        ErrorKind::InvalidArgument,
        "render_adaptive_pass: a resumed render has no variance estimates; it continues with uniform passes");
  if (!film.has_deviations()) {  // the warm-up leaves at least 2 samples in every pixel, or no spp
    const int warmup = std::min(spp, std::max(1, adaptive_warmup_spp(spp) - film.spp()));
    if (!render_pass(warmup, cancel, on_tile)) return false;
    spp -= warmup;
    if (spp == 0) return true;
  }
  const int width = impl_->settings.width;
  const std::vector<uint32_t> counts =
      allocate_samples(allocation_weights(film.deviations(), film.costs()), width, impl_->settings.height,
                       uint64_t(spp) * uint64_t(width) * uint64_t(impl_->settings.height),
                       impl_->settings.seed, impl_->adaptive_passes++);
  const auto runs = [&film, &counts, width](int x, int y) {
    return SampleRun{film.count(x, y), counts[size_t(y) * size_t(width) + size_t(x)]};
  };
  if (!impl_->render_into_film(cancel, on_tile, runs)) return false;
  film.merge_pass(counts);
  return true;
}

std::optional<RangePartial> Renderer::render_range(SampleRange range, const std::atomic<bool>& cancel,
                                                   const std::function<void()>& on_tile) {
  if (range.end <= range.first) throw Error(ErrorKind::InvalidArgument, "render_range: an empty range");
  const uint64_t rays_before = impl_->rays.load();
  const RenderSettings& s = impl_->settings;
  RangePartial out{range, 0, PartialFilm(s.width, s.height, s.passes)};
  const auto runs = [range](int, int) { return SampleRun{range.first, uint32_t(range.count())}; };
  const auto store = [&out, range, &s](int x, int y, Rgb sum, float, uint32_t, const float* aux) {
    out.film.add(size_t(y) * size_t(s.width) + size_t(x), sum, uint32_t(range.count()), aux);
  };
  const bool finished =
      for_each_tile(tile_count(), cancel, on_tile, [&](int t) { impl_->render_tile(t, runs, store); });
  if (!finished) return std::nullopt;
  out.rays = impl_->rays.load() - rays_before;
  return out;
}

void Renderer::resume(const Image& mean, int spp) {
  impl_->film.restore(mean, spp);
}

int Renderer::spp_done() const {
  return impl_->film.spp();
}

Image Renderer::image() const {
  return impl_->film.mean();
}

Image Renderer::image(AuxPass pass) const {
  return impl_->film.mean(pass);
}

void Renderer::resume(AuxPass pass, const Image& mean) {
  impl_->film.restore(pass, mean);
}

RenderStats Renderer::stats() const {
  return {impl_->samples.load(std::memory_order_relaxed), impl_->rays.load(std::memory_order_relaxed)};
}

}  // namespace lp::render

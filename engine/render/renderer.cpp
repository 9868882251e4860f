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
#include "engine/render/bsdf.hpp"
#include "engine/render/camera.hpp"
#include "engine/render/directional_lights.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/film.hpp"
#include "engine/render/integrator.hpp"
#include "engine/render/path_sampler.hpp"
#include "engine/render/sun_light.hpp"

namespace lp::render {
namespace {

inline constexpr int kTileSize = 16;
inline constexpr int kPacket = EmbreeScene::kPacket;

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
            {lighting.mode, s.max_depth, lighting.visible, camera.pixel_spread(), s.mipmaps, s.normal_maps}),
        film(s.width, s.height),
        tiles_x((s.width + kTileSize - 1) / kTileSize),
        tiles_y((s.height + kTileSize - 1) / kTileSize) {}

  static bool uses_lights(LightingMode m) {
    return m == LightingMode::MedianCut || m == LightingMode::MedianCutAll;
  }

  // Renders `spp` samples from `first_sample` of every pixel of the tile, handing each pixel's sum to
  // `store(x, y, sum)`. The camera rays of one sample index in a run of kPacket pixels of a row are
  // traced as one packet: which pixels share a packet depends only on the tile, so a pass, a range of
  // samples or another thread count traces every ray alike. Each pixel adds its samples in index order.
  template <class Store>
  void render_tile(int tile, uint32_t first_sample, int spp, Store&& store) {
    const FlushDenormals ftz;
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, settings.width), y1 = std::min(y0 + kTileSize, settings.height);
    uint64_t tile_rays = 0;
    for (int y = y0; y < y1; ++y) {
      for (int xs = x0; xs < x1; xs += kPacket) {
        const int n = std::min(kPacket, x1 - xs);
        Rgb sums[kPacket] = {};
        for (int i = 0; i < spp; ++i) trace_packet(xs, y, n, first_sample + uint32_t(i), sums, tile_rays);
        for (int k = 0; k < n; ++k) store(xs + k, y, sums[k]);
      }
    }
    samples.fetch_add(uint64_t(x1 - x0) * uint64_t(y1 - y0) * uint64_t(spp), std::memory_order_relaxed);
    rays.fetch_add(tile_rays, std::memory_order_relaxed);
  }

  // Sample `index` of the n pixels (x, y) .. (x + n - 1, y), added to sums[0 .. n).
  void trace_packet(int x, int y, int n, uint32_t index, Rgb* sums, uint64_t& tile_rays) const {
    std::optional<PathSampler> samplers[kPacket];
    Ray camera_rays[kPacket];
    std::optional<SurfaceHit> hits[kPacket];
    for (int k = 0; k < n; ++k) {
      const uint64_t pixel = uint64_t(y) * uint64_t(settings.width) + uint64_t(x + k);
      PathSampler& sampler = samplers[k].emplace(settings.seed, pixel, index);
      const Point2 jitter = sampler.get_2d();
      camera_rays[k] = camera.generate(float(x + k) + jitter.x, float(y) + jitter.y);
    }
    geometry.intersect_packet({camera_rays, size_t(n)}, {hits, size_t(n)});
    for (int k = 0; k < n; ++k) {
      const Rgb l = integrator.radiance(camera_rays[k], hits[k], *samplers[k], tile_rays);
      if (finite(l)) sums[k] += l;  // a numerical failure must not poison the image
    }
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
};

Renderer::Renderer(const SceneDesc& scene, const Lighting& lighting, const RenderSettings& settings,
                   std::shared_ptr<const EnvMap> envmap) {
  scene.validate("scene");
  lighting.validate("lighting");
  settings.validate("settings");
  impl_ = std::make_unique<Impl>(scene, lighting, settings, std::move(envmap));
}

Renderer::~Renderer() = default;

int Renderer::tile_count() const {
  return impl_->tiles_x * impl_->tiles_y;
}

bool Renderer::render_pass(int spp, const std::atomic<bool>& cancel, const std::function<void()>& on_tile) {
  if (spp < 1) throw Error(ErrorKind::InvalidArgument, "render_pass: spp must be >= 1");
  const uint32_t first = uint32_t(impl_->film.spp());
  Film& film = impl_->film;
  const bool finished = for_each_tile(tile_count(), cancel, on_tile, [&](int t) {
    impl_->render_tile(t, first, spp, [&film](int x, int y, Rgb sum) { film.set_pass_sum(x, y, sum); });
  });
  if (!finished) return false;
  film.merge_pass(spp);
  return true;
}

std::optional<RangePartial> Renderer::render_range(SampleRange range, const std::atomic<bool>& cancel,
                                                   const std::function<void()>& on_tile) {
  if (range.end <= range.first) throw Error(ErrorKind::InvalidArgument, "render_range: an empty range");
  const uint64_t rays_before = impl_->rays.load();
  RangePartial out{range, 0, PartialFilm(impl_->settings.width, impl_->settings.height)};
  const auto store = [&out, range](int x, int y, Rgb sum) {
    out.film.add(x, y, sum, uint32_t(range.count()));
  };
  const bool finished = for_each_tile(tile_count(), cancel, on_tile, [&](int t) {
    impl_->render_tile(t, range.first, range.count(), store);
  });
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

RenderStats Renderer::stats() const {
  return {impl_->samples.load(std::memory_order_relaxed), impl_->rays.load(std::memory_order_relaxed)};
}

}  // namespace lp::render

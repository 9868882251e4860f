#pragma once
// A progressive, tiled, multi-threaded path tracer over an Embree scene lit by an environment map.
// The caller (a job) drives it pass by pass; each pass adds samples to every pixel, so a valid image
// exists after the first pass. Cancellation is checked per tile; progress is reported per tile.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "engine/render/partial_film_codec.hpp"
#include "engine/render/pass_schedule.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct RenderStats {
  uint64_t samples = 0;  // camera samples (pixel samples) traced so far, over all pixels
  uint64_t rays = 0;     // all rays traced (camera, bounce, shadow)
};

class Renderer {
 public:
  // Builds the Embree scene (loads meshes), the camera and the lights. Throws lp::Error on bad input
  // (InvalidArgument for an unusable scene or camera, NotFound / Corrupt for a mesh file).
  Renderer(const SceneDesc& scene, const Lighting& lighting, const RenderSettings& settings,
           std::shared_ptr<const EnvMap> envmap);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int tile_count() const;
  // Adds `spp` samples per pixel (each pixel continues its own sequence of samples). Runs in parallel
  // (oneTBB) in the caller's task arena; calls `on_tile` after each finished tile (from worker
  // threads). Returns false if `cancel` became true (the pass is then incomplete and not added to the
  // image).
  bool render_pass(int spp, const std::atomic<bool>& cancel, const std::function<void()>& on_tile);

  // Adaptive sampling: adds spp x width x height samples in all, shared among the pixels in
  // proportion to their neighbours' standard deviations (adaptive_allocation.hpp: the rule, and why a
  // pixel's count never reads its own samples, which keeps every pixel's mean unbiased). A render
  // whose passes gave fewer than 2 samples per pixel first spends a uniform warm-up
  // (adaptive_warmup_spp, part of the `spp`); the deviations are measured on the uniform samples
  // before the first adaptive pass and kept. Uniform and adaptive passes mix freely. Cancelled as
  // render_pass (a finished warm-up stays in the image). Throws InvalidArgument after resume(): a
  // restored mean image has no deviations. render_range() and resume() are uniform only.
  bool render_adaptive_pass(int spp, const std::atomic<bool>& cancel, const std::function<void()>& on_tile);
  // One pass of render_passes(): render_adaptive_pass or render_pass as it says.
  bool render(const RenderPass& pass, const std::atomic<bool>& cancel, const std::function<void()>& on_tile);

  // Renders the samples [range.first, range.end) of every pixel into a partial film of their own (the
  // image and spp_done() stay as they are): the samples a run of uniform passes draws at those indices, so
  // partials of a render's ranges merge into its image. May run while no pass runs; not concurrently
  // with another range. nullopt if `cancel` became true (checked per tile). rays counts this range's
  // rays only when no other range or pass runs meanwhile.
  std::optional<RangePartial> render_range(SampleRange range, const std::atomic<bool>& cancel,
                                           const std::function<void()>& on_tile = {});

  // Continues an earlier run of the same scene and settings from its mean image over `spp` samples
  // per pixel: later passes draw the samples that run would have drawn next. Call before any pass.
  void resume(const Image& mean, int spp);
  // The same for an auxiliary pass the settings ask for, after resume() of the colour.
  void resume(AuxPass pass, const Image& mean);

  int spp_done() const;  // samples per pixel so far (their mean, to the nearest, after adaptive passes)
  Image image() const;   // mean of the finished passes (linear radiance)
  // The mean of an auxiliary pass the settings ask for (aux_passes.hpp: alpha and depth as greys).
  Image image(AuxPass pass) const;
  RenderStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lp::render

#include "server/turntables/turntable_job.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

#include "api/api_error.hpp"
#include "api/turntable_schema.hpp"
#include "engine/core/error.hpp"
#include "engine/render/renderer.hpp"
#include "engine/render/scene_view.hpp"
#include "server/renders/render_memory.hpp"

namespace lp::server {

std::vector<render::Camera> turntable_cameras(const api::TurntableRequest& request) {
  const auto& s = request.render.settings;
  const float aspect = float(s.width) / float(std::max(1, s.height));
  render::SceneDesc scene = request.render.scene;
  std::vector<render::Camera> cameras;
  for (int i = 0; i < request.turntable.frames; ++i) {
    scene.camera.fit = render::turntable_fit(request.turntable, i);
    scene.camera.gltf.reset();
    try {
      cameras.push_back(render::resolve_camera(scene, aspect));
    } catch (const Error& e) {
      if (e.field().empty()) throw;
      throw api::invalid_field(request.turntable.object ? "turntable.object" : "turntable", e.problem());
    }
  }
  return cameras;
}

int64_t turntable_bytes(const api::TurntableRequest& request, int64_t triangles) {
  const auto& s = request.render.settings;
  const int64_t images = s.background.mode == render::BackgroundMode::Transparent ? 2 : 1;
  return running_render_bytes(s, triangles) +
         request.turntable.frames * images * EnvMap::image_bytes(s.width, s.height);
}

TurntableJob::TurntableJob(std::string id, api::TurntableRequest request, std::vector<render::Camera> cameras,
                           std::shared_ptr<const EnvMap> envmap, TurntableJobContext context)
    : Job(std::move(id)),
      request_(std::move(request)),
      cameras_(std::move(cameras)),
      envmap_(std::move(envmap)),
      counters_(context.counters),
      memory_(std::move(context.memory)) {
  set_work(request_.turntable.frames, 0);  // until run() counts in tiles
}

std::vector<RenderImage> TurntableJob::frames() const {
  std::lock_guard lock(mutex_);
  return frames_;
}

int64_t TurntableJob::retained_bytes() const {
  std::lock_guard lock(mutex_);
  int64_t bytes = 0;
  for (const RenderImage& frame : frames_) {
    bytes += int64_t(frame.image->data().size_bytes());
    for (const auto& pass : frame.passes)
      if (pass) bytes += int64_t(pass->data().size_bytes());
  }
  return bytes;
}

void TurntableJob::ending(JobStatus, const std::optional<JobError>&) {
  envmap_.reset();
  memory_.resize(std::min(memory_.bytes(), retained_bytes()));
  memory_.set_use(MemoryUse::Held);
}

// Renders frame `index` through all its passes; nullopt when a cancel stopped it. `frame_work` is the
// work units of one frame, set by the first.
std::optional<RenderImage> TurntableJob::render_frame(int index, int64_t& frame_work) {
  using Clock = std::chrono::steady_clock;
  const auto& r = request_.render;
  render::SceneDesc scene = r.scene;
  scene.camera = cameras_[size_t(index)];
  render::Renderer renderer(scene, r.lighting, r.settings, envmap_);
  if (frame_work == 0) {
    frame_work = int64_t(renderer.tile_count()) * r.settings.spp;
    set_work(frame_work * request_.turntable.frames, frame_work * index);
  }
  const auto start = Clock::now();
  for (const render::RenderPass& pass : render::render_passes(r.settings)) {
    const auto on_tile = [this, spp = pass.spp] { add_work_done(spp); };
    if (!renderer.render(pass, cancel_flag(), on_tile)) return std::nullopt;
  }
  if (counters_) {
    const render::RenderStats stats = renderer.stats();
    counters_->add(stats.samples, stats.rays, std::chrono::duration<double>(Clock::now() - start).count());
  }
  RenderImage frame{std::make_shared<const Image>(renderer.image()), r.settings.spp, {}};
  if (r.settings.background.mode == render::BackgroundMode::Transparent)
    frame.passes[size_t(render::AuxPass::Alpha)] =
        std::make_shared<const Image>(renderer.image(render::AuxPass::Alpha));
  return frame;
}

bool TurntableJob::run() {
  const auto& s = request_.render.settings;
  spdlog::info("turntable {} started: {} frames of {}x{}, {} spp, envmap '{}'", id(), frame_count(), s.width,
               s.height, s.spp, request_.render.envmap);
  int64_t frame_work = 0;
  for (int i = 0; i < frame_count(); ++i) {
    if (interrupt_requested()) return false;
    auto frame = render_frame(i, frame_work);
    if (!frame) return false;
    std::lock_guard lock(mutex_);
    frames_.push_back(std::move(*frame));
  }
  spdlog::info("turntable {} done after {:.2f} s", id(), elapsed_s());
  return true;
}

void TurntableJob::describe(nlohmann::json& out) const {
  const auto& s = request_.render.settings;
  std::lock_guard lock(mutex_);
  out["frames"] = request_.turntable.frames;
  out["frames_done"] = frames_.size();
  out["width"] = s.width;
  out["height"] = s.height;
  out["spp"] = s.spp;
  out["envmap"] = request_.render.envmap;
  out["cameras"] = api::describe_turntable_cameras(cameras_);
}

}  // namespace lp::server

#include "server/render_job.hpp"

#include <algorithm>
#include <chrono>

#include <spdlog/spdlog.h>

namespace lp::server {

std::vector<int> pass_schedule(int spp, int max_pass) {
  std::vector<int> passes;
  int done = 0, next = 1;
  while (done < spp) {
    const int pass = std::min(next, spp - done);
    passes.push_back(pass);
    done += pass;
    if (passes.size() > 1) next = std::min(2 * next, max_pass);
  }
  return passes;
}

RenderJob::RenderJob(std::string id, api::RenderRequest request, std::shared_ptr<const EnvMap> envmap)
    : Job(std::move(id)), request_(std::move(request)), envmap_(std::move(envmap)) {}

RenderImage RenderJob::image() const {
  std::lock_guard lock(mutex_);
  return {image_, spp_done_};
}

int RenderJob::spp_done() const {
  std::lock_guard lock(mutex_);
  return spp_done_;
}

int64_t RenderJob::retained_bytes() const {
  std::lock_guard lock(mutex_);
  return image_ ? int64_t(image_->data().size_bytes()) : 0;
}

void RenderJob::publish(const render::Renderer& renderer, double render_s) {
  auto image = std::make_shared<const Image>(renderer.image());
  std::lock_guard lock(mutex_);
  image_ = std::move(image);
  spp_done_ = renderer.spp_done();
  stats_ = renderer.stats();
  render_s_ = render_s;
}

bool RenderJob::run() {
  using Clock = std::chrono::steady_clock;
  const auto& s = request_.settings;
  spdlog::info("render {} started: {}x{}, {} spp, depth {}, envmap '{}', {}, lighting {}", id(), s.width, s.height,
               s.spp, s.max_depth, request_.envmap,
               request_.preset ? "preset " + *request_.preset : std::to_string(request_.scene.objects.size()) + " objects",
               api::lighting_mode_name(request_.lighting.mode));
  auto release = [this](const char* how) {
    envmap_.reset();
    spdlog::info("render {} {} after {:.2f} s ({} spp done)", id(), how, elapsed_s(), spp_done());
  };
  try {
    render::Renderer renderer(request_.scene, request_.lighting, s, envmap_);
    const auto passes = pass_schedule(s.spp);
    const int64_t tiles = renderer.tile_count();
    set_work_total(tiles * s.spp);
    const auto start = Clock::now();
    for (const int pass : passes) {
      if (!renderer.render_pass(pass, cancel_flag(), [this, pass] { add_work_done(pass); })) {
        release("cancelled");
        return false;
      }
      publish(renderer, std::chrono::duration<double>(Clock::now() - start).count());
    }
  } catch (const std::exception& e) {
    release("failed");
    spdlog::warn("render {} failed: {}", id(), e.what());
    throw;
  }
  release("done");
  return true;
}

void RenderJob::describe(nlohmann::json& out) const {
  const auto& s = request_.settings;
  std::lock_guard lock(mutex_);
  out["spp_done"] = spp_done_;
  out["spp"] = s.spp;
  out["width"] = s.width;
  out["height"] = s.height;
  out["max_depth"] = s.max_depth;
  out["seed"] = s.seed;
  out["envmap"] = request_.envmap;
  out["scene"] = request_.preset ? nlohmann::json{{"preset", *request_.preset}}
                                 : nlohmann::json{{"objects", request_.scene.objects.size()}};
  out["lighting_mode"] = api::lighting_mode_name(request_.lighting.mode);
  out["samples"] = stats_.samples;
  out["rays"] = stats_.rays;
  out["samples_per_s"] = render_s_ > 0 ? double(stats_.samples) / render_s_ : 0.0;
  out["rays_per_s"] = render_s_ > 0 ? double(stats_.rays) / render_s_ : 0.0;
  out["image_available"] = image_ != nullptr;
}

}  // namespace lp::server

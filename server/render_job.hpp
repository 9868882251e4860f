#pragma once
// A render as a background job: builds the renderer, then renders progressive passes (1, 1, 2, 4, ...
// samples per pixel, capped) so a valid image exists after the first pass. Progress counts pixel samples
// per finished tile; the image and the statistics are published after every pass.
#include <memory>
#include <mutex>
#include <vector>

#include "api/render_request.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "engine/render/renderer.hpp"
#include "server/job.hpp"

namespace lp::server {

// Samples per pixel of each pass: 1, 1, 2, 4, ... doubling up to `max_pass`, then `max_pass` until done
// (the last pass takes the remainder). Sums to `spp`.
std::vector<int> pass_schedule(int spp, int max_pass = 32);

struct RenderImage {
  std::shared_ptr<const Image> image;  // the mean of the finished passes; nullptr before the first
  int spp_done = 0;                    // samples per pixel in it
};

class RenderJob : public Job {
 public:
  RenderJob(std::string id, api::RenderRequest request, std::shared_ptr<const EnvMap> envmap);

  RenderImage image() const;
  int spp_done() const;
  const api::RenderRequest& request() const { return request_; }
  int64_t retained_bytes() const override;

 protected:
  bool run() override;
  void describe(nlohmann::json& out) const override;

 private:
  void publish(const render::Renderer& renderer, double render_s);

  const api::RenderRequest request_;
  std::shared_ptr<const EnvMap> envmap_;  // released when the job ends

  mutable std::mutex mutex_;
  std::shared_ptr<const Image> image_;
  int spp_done_ = 0;
  render::RenderStats stats_;
  double render_s_ = 0;  // time spent in passes (not building the scene), for the rates
};

}  // namespace lp::server

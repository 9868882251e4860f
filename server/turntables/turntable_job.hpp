#pragma once
// A turntable as one background job: its frames rendered in order, each a whole render (the request's
// settings and progressive passes) from its own camera. Progress is over all frames: the frames done
// plus the part of the current one. The cameras are placed when the job is made (the models are loaded
// then), so the status lists them from the start. Finished frames are kept in memory, in the budget
// reserved for all of them when the job was accepted; nothing is kept across restarts (a turntable is
// made again by a new request).
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "api/turntable_request.hpp"
#include "engine/core/memory_budget.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "server/jobs/job.hpp"
#include "server/renders/render_counters.hpp"
#include "server/renders/render_job_image.hpp"

namespace lp::server {

// The cameras of every frame of `request`'s turntable, its models loaded; a 400 naming `turntable` when
// there is nothing to frame.
std::vector<render::Camera> turntable_cameras(const api::TurntableRequest& request);

// What a turntable reserves from the budget: a render's working memory and every frame it keeps (with
// its alpha when the background is transparent).
int64_t turntable_bytes(const api::TurntableRequest& request, int64_t triangles);

struct TurntableJobContext {
  MemoryReservation memory;            // turntable_bytes, shrunk to the frames kept when the job ends
  RenderCounters* counters = nullptr;  // the server's counters each finished frame adds to; null: none
};

class TurntableJob : public Job {
 public:
  TurntableJob(std::string id, api::TurntableRequest request, std::vector<render::Camera> cameras,
               std::shared_ptr<const EnvMap> envmap, TurntableJobContext context);

  const api::TurntableRequest& request() const { return request_; }
  const std::vector<render::Camera>& cameras() const { return cameras_; }
  int frame_count() const { return request_.turntable.frames; }
  // The frames finished so far, in order (frame i at index i): each one's colour, with its alpha pass when
  // the background is transparent.
  std::vector<RenderImage> frames() const;
  int64_t retained_bytes() const override;

 protected:
  bool run() override;
  void describe(nlohmann::json& out) const override;
  void ending(JobStatus, const std::optional<JobError>&) override;

 private:
  std::optional<RenderImage> render_frame(int index, int64_t& frame_work);

  const api::TurntableRequest request_;
  const std::vector<render::Camera> cameras_;
  std::shared_ptr<const EnvMap> envmap_;  // released when the job ends
  RenderCounters* const counters_;
  MemoryReservation memory_;

  mutable std::mutex mutex_;
  std::vector<RenderImage> frames_;
};

}  // namespace lp::server

#pragma once
// A render as a background job: builds the renderer, then renders progressive passes (1, 1, 2, 4, ...
// samples per pixel, capped: render::render_passes) so a valid image exists after the first pass. Progress
// counts pixel samples per finished tile; the image and the statistics are published after every pass, and
// with a state store the job keeps its record and image there after every pass, so a restart can continue it.
// Split over Redis (or continuing such a render without Redis), it renders sample ranges instead, publishes
// the image as each range is merged and keeps it every few seconds. A render that asks for `denoise`
// denoises its colour once every sample is done, on the job's thread (the last tenth of its progress, and
// cancelled like a pass), then publishes and keeps the denoised colour beside the image.
#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "api/render_request.hpp"
#include "engine/denoise/denoiser.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "engine/render/pass_schedule.hpp"
#include "engine/render/renderer.hpp"
#include "server/jobs/job.hpp"
#include "server/renders/render_counters.hpp"
#include "server/renders/render_files.hpp"
#include "server/renders/render_job_image.hpp"
#include "server/renders/render_record.hpp"
#include "server/scale_out/scale_out.hpp"
#include "server/storage/state_store.hpp"

namespace lp::server {

// What a render job works with beside its request.
struct RenderJobContext {
  StateStore* store = nullptr;         // where it keeps its record and image; null keeps nothing
  RenderCounters* counters = nullptr;  // the server's counters it adds each finished pass to; null: none
  MemoryReservation memory;            // its reservation in the budget (renders/render_memory.hpp)
  std::optional<ScaleOut> scale_out;   // splits it into work items on Redis (render_coordinator.hpp)
  const denoise::Denoiser* denoiser = nullptr;  // for a request with `denoise`; null for a job that ended
};

class RenderJob : public Job {
 public:
  // `record` is a fresh one for a new render, or the record of an earlier run to continue (then `image`
  // is its mean image over record.spp_done samples per pixel, with its passes). `envmap` may be null for a
  // job that has ended. The reservation shrinks to the kept image when the job ends.
  RenderJob(RenderRecord record, api::RenderRequest request, std::shared_ptr<const EnvMap> envmap,
            RenderImage image, RenderJobContext context);

  RenderImage image() const;
  int spp_done() const;
  const api::RenderRequest& request() const { return request_; }
  RenderRecord record() const;
  RenderRecord record(JobStatus status, const std::optional<JobError>& error) const;
  int64_t retained_bytes() const override;

  void save_record() const { files_.save_record(record()); }  // to the store (a failure is logged)
  void keep_record() const { files_.keep_record(record()); }  // the same, throwing (RenderFiles::keep_record)
  void delete_state() { files_.remove(); }                    // the record and the image, for good

 protected:
  bool run() override;
  void describe(nlohmann::json& out) const override;
  void ending(JobStatus status, const std::optional<JobError>& error) override {
    keep_result_memory();
    files_.save_record(record(status, error));
  }
  void forgotten() override { delete_state(); }

 private:
  bool render_here();
  bool render_split();
  bool render_ranges_here();
  // The ranges done and the film holding them, from the image of an earlier run.
  std::vector<render::SampleRange> done_ranges() const;
  render::PartialFilm done_film() const;
  // What a merged range changes: the ranges done, the image, the statistics and, every few seconds,
  // the stored image.
  struct RangeRun;
  void merged(RangeRun& run, const render::PartialFilm& film, render::SampleRange range, uint64_t rays);
  // The image over `spp_done` samples per pixel (in `ranges_done` when they are not [0, spp_done)), and
  // what this run traced for it in `render_s`.
  void publish(Image image, PassImages passes, int spp_done, render::RenderStats run_stats, double render_s,
               std::vector<render::SampleRange> ranges_done = {});
  void checkpoint();
  // The work units of the render, and the total with the denoise's share.
  void set_render_work(int64_t total, int64_t done);
  // The colour of the finished render denoised, published and kept; false if a cancel or a stop ended it.
  bool denoise_result();
  void keep_result_memory();  // the image of the passes done, then the record naming it
  int skip_done_passes(std::vector<render::RenderPass>& passes) const;

  const api::RenderRequest request_;
  const nlohmann::json request_json_;
  std::shared_ptr<const EnvMap> envmap_;  // released when the job ends
  RenderCounters* const counters_;
  const std::optional<ScaleOut> scale_out_;
  const denoise::Denoiser* const denoiser_;
  int64_t render_work_ = 0;                  // the work units of the render, before the denoise's
  const render::RenderStats earlier_stats_;  // of earlier runs
  const double earlier_render_s_;

  mutable std::mutex mutex_;
  std::shared_ptr<const Image> image_;
  PassImages passes_;
  std::shared_ptr<const Image> denoised_;  // image_ denoised, once every sample is done
  std::optional<double> denoise_s_;
  int spp_done_ = 0;
  std::vector<render::SampleRange> ranges_done_;  // see RenderRecord::ranges_done
  render::RenderStats stats_;
  double render_s_ = 0;             // time spent in passes (not building the scene), for the rates
  std::string envmap_fingerprint_;  // of the map the kept image was rendered with
  ModelHashes model_hashes_;        // of the models the kept image was rendered with
  ModelHashes run_model_hashes_;    // of this run's models, hashed when it starts

  MemoryReservation memory_;
  RenderFiles files_;
};

}  // namespace lp::server

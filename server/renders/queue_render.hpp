#pragma once
// Queuing a render job, new or continued after an interruption: the one way a render reaches the runners.
#include <memory>
#include <nlohmann/json.hpp>

#include "server/app.hpp"
#include "server/renders/render_job.hpp"

namespace lp::server {

struct QueuedRender {
  std::shared_ptr<RenderJob> job;  // null: the queue was full
  nlohmann::json status;           // the job's status as queued, before a runner could pick it up
};

// Reserves the render's memory (throws MemoryBudgetError when it does not fit), builds its job with the
// server's context (state store, counters, scale-out) and writes its record before a runner can pick it
// up (throws api::ApiError 507 insufficient_storage or 500 write_failed, queuing nothing, when the record
// cannot be written). `image` continues an interrupted render: its mean over record.spp_done samples per
// pixel and its passes, and `replaced` the interrupted job the new one replaces under the same id. When the
// queue is full, the stored record is put back as it was: removed for a new render, `replaced`'s again for a
// continuation (unless another continuation took its place meanwhile).
// A request with `denoise` is refused (503 denoiser_unavailable) by a server without the denoiser's weights.
QueuedRender queue_render(App& app, RenderRecord record, api::RenderRequest request,
                          std::shared_ptr<const EnvMap> envmap, int64_t triangles, RenderImage image = {},
                          const RenderJob* replaced = nullptr);

// Throws api::ApiError 503 denoiser_unavailable when the server's denoiser has no weights.
void require_denoiser(const App& app);

}  // namespace lp::server

#include "server/renders/queue_render.hpp"

#include "api/api_error.hpp"
#include "server/renders/render_memory.hpp"

namespace lp::server {

void require_denoiser(const App& app) {
  if (app.denoiser.available()) return;
  throw api::ApiError(api::ErrorCode::DenoiserUnavailable,
                      "this server has no denoiser weights (the rt_*.tza files of --denoise-weights, or its "
                      "default folder); ask without \"denoise\" or give the server the weights");
}

QueuedRender queue_render(App& app, RenderRecord record, api::RenderRequest request,
                          std::shared_ptr<const EnvMap> envmap, int64_t triangles, RenderImage image,
                          const RenderJob* replaced) {
  const auto& s = request.settings;
  if (request.denoise) require_denoiser(app);
  RenderJobContext context{
      app.state.get(), &app.render_counters, reserve_render(app.memory, s, triangles, request.denoise),
      scale_out(app.options.scale_out, app.bundles, app.scale_out_counters), &app.denoiser};
  auto job = std::make_shared<RenderJob>(std::move(record), std::move(request), std::move(envmap),
                                         std::move(image), std::move(context));
  QueuedRender queued{job, job->status_json()};
  job->keep_record();
  if (app.renders.submit(job)) return queued;
  if (!replaced)
    job->delete_state();
  else if (app.renders.find(replaced->id()).get() == replaced)
    replaced->save_record();
  return {};
}

}  // namespace lp::server

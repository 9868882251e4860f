// Render jobs: POST /api/v1/renders queues a render; status, image (the current pass while running),
// server-sent progress events, cancel / remove, resume (an interrupted render), and the list of jobs.
#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <memory>

#include "api/api_error.hpp"
#include "api/preview_params.hpp"
#include "api/render_image_pass.hpp"
#include "api/render_request.hpp"
#include "api/thumbnail_params.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/resize.hpp"
#include "server/http/reserved_content.hpp"
#include "server/renders/event_streams.hpp"
#include "server/renders/queue_render.hpp"
#include "server/renders/render_job.hpp"
#include "server/renders/render_pictures.hpp"
#include "server/renders/scene_meshes.hpp"
#include "server/renders/stored_renders.hpp"
#include "server/routes/job_answers.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<RenderJob> find_render(const App& app, const std::string& id) {
  auto job = std::dynamic_pointer_cast<RenderJob>(app.renders.find(id));
  if (!job) throw api::not_found("no render job '" + api::excerpt(id) + "'");
  return job;
}

std::string render_url(const RenderJob& job) {
  return "/api/v1/renders/" + job.id();
}

void submit(App& app, const httplib::Request& req, httplib::Response& res) {
  refuse_on_worker(app, "render");
  RenderRecord record;
  record.id = app.renders.new_id();
  record.request = api::parse_json_object(req.body);
  auto request = api::parse_render_request(record.request, app.options.limits);
  const auto envmap = app.envmaps.find(request.envmap);
  if (!envmap)
    throw api::invalid_field("envmap", "no environment map '" + api::excerpt(request.envmap) + "' is loaded");
  const int64_t triangles = resolve_meshes(request.scene, app);
  resolve_view(request);
  const auto queued = queue_render(app, std::move(record), std::move(request), envmap->map, triangles);
  if (!queued.job) return send_queue_full(app.renders, "renders", res);
  send_accepted(render_url(*queued.job), queued.status, res);
}

void resume(App& app, const httplib::Request& req, httplib::Response& res) {
  refuse_on_worker(app, "render");
  const auto queued = resume_render(app, find_render(app, path_param(req, 1)));
  if (!queued.job) return send_queue_full(app.renders, "renders", res);
  send_accepted(render_url(*queued.job), queued.status, res);
}

void list(const App& app, httplib::Response& res) {
  nlohmann::json renders = nlohmann::json::array();
  for (const auto& job : app.renders.list()) renders.push_back(job->status_json());
  send_json(res, {{"renders", renders},
                  {"running", app.renders.running_count()},
                  {"queued", app.renders.queued_count()},
                  {"max_running", app.options.jobs.max_running},
                  {"max_queued", app.options.jobs.max_queued}});
}

void image(const App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_render(app, path_param(req, 1));
  const auto params = api::parse_preview_params(req.params, ImageFormat::Png, job->request().tone_mapping);
  const auto pass = api::parse_render_image_pass(req.params);
  const RenderImage current = job->image();
  if (!current.image)
    throw api::ApiError(
        api::ErrorCode::NoImageYet,
        fmt::format("render '{}' is {} and has no finished pass yet", job->id(), enum_name(job->status())));
  const auto size = api::parse_image_size(req.params);  // a thumbnail, resampled in linear light
  const RenderImage pictures = size ? fit_longest_side(current, size) : current;
  const auto& settings = job->request().settings;
  auto memory = app.memory.reserve(
      api::render_picture_bytes(pass, params, settings.width, settings.height, settings.passes.list().size()),
      MemoryUse::Transient, std::string("encoding a render as ") + enum_name(params.format));
  res.set_header("X-Spp-Done", std::to_string(current.spp_done));
  send_reserved(res, api::encode_render_picture(pictures_of(pictures, settings), pass, params),
                format_mime_type(params.format), std::move(memory));
}

void cancel(App& app, const httplib::Request& req, httplib::Response& res) {
  cancel_or_remove(app.renders, *find_render(app, path_param(req, 1)), "render job", res);
}

struct EventStream {
  std::shared_ptr<RenderJob> job;
  std::unique_ptr<StreamSlot> slot;
  std::string last_data;
  std::chrono::steady_clock::time_point last_write = std::chrono::steady_clock::now();
  bool first = true;
};

bool write_text(httplib::DataSink& sink, const std::string& text) {
  return sink.write(text.data(), text.size());
}

// Called by httplib again and again until it returns false or calls sink.done(). Each call waits up to
// 250 ms for the job to end, then sends a progress event if the status changed (or a comment every 2 s
// so a vanished client is noticed). When the job ends it sends the final status as "end" and closes.
bool next_event(EventStream& s, httplib::DataSink& sink) {
  if (!sink.is_writable()) return false;
  const bool finished = s.job->wait_finished_for(s.first ? 0ms : 250ms);
  s.first = false;
  const std::string data = s.job->status_json().dump();
  if (finished) {
    const bool ok = write_text(sink, "event: end\ndata: " + data + "\n\n");
    sink.done();
    return ok;
  }
  const auto now = std::chrono::steady_clock::now();
  std::string text;
  if (data != s.last_data)
    text = "event: progress\ndata: " + data + "\n\n";
  else if (now - s.last_write > 2s)
    text = ": waiting\n\n";
  if (text.empty()) return true;
  s.last_data = data;
  s.last_write = now;
  return write_text(sink, text);
}

void events(App& app, const httplib::Request& req, httplib::Response& res) {
  auto state = std::make_shared<EventStream>();
  state->job = find_render(app, path_param(req, 1));
  state->slot = std::make_unique<StreamSlot>(app.event_streams, app.options.max_event_streams);
  if (!state->slot->acquired()) {
    res.set_header("Retry-After", "5");
    send_error(res, api::ErrorCode::TooManyStreams,
               fmt::format("{} event streams are open (the limit); poll GET /api/v1/renders/{} instead",
                           app.options.max_event_streams, state->job->id()));
    return;
  }
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream", [state](size_t, httplib::DataSink& sink) { return next_event(*state, sink); });
}

}  // namespace

void register_render_routes(Router& router, App& app) {
  router.post("/api/v1/renders", endpoint_of(app, submit));
  router.get("/api/v1/renders", [&app](const httplib::Request&, httplib::Response& res) { list(app, res); });
  router.get("/api/v1/renders/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    send_json(res, find_render(app, path_param(req, 1))->status_json());
  });
  router.get("/api/v1/renders/{id}/image", endpoint_of(app, image), Caching::Revalidate);
  router.get("/api/v1/renders/{id}/events", endpoint_of(app, events));
  router.post("/api/v1/renders/{id}/resume", endpoint_of(app, resume));
  router.del("/api/v1/renders/{id}", endpoint_of(app, cancel));
}

}  // namespace lp::server

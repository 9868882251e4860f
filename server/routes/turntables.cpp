// Turntables: POST /api/v1/turntables queues the frames of an orbit round a framed model as one job;
// status (with every frame's camera), cancel / remove, the list; each frame as an image, and the frames
// together as a zip, a contact sheet and an animated WebP. 8-bit answers are tone mapped with the
// request's `tone_mapping` (default `neutral`) unless the query names another curve.
#include <fmt/format.h>

#include <charconv>
#include <memory>

#include "api/api_error.hpp"
#include "api/excerpt.hpp"
#include "api/preview_params.hpp"
#include "api/thumbnail_params.hpp"
#include "api/turntable_request.hpp"
#include "api/turntable_schema.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/webp.hpp"
#include "server/http/reserved_content.hpp"
#include "server/renders/render_pictures.hpp"
#include "server/renders/scene_meshes.hpp"
#include "server/routes/job_answers.hpp"
#include "server/routes/routes.hpp"
#include "server/turntables/turntable_job.hpp"
#include "server/turntables/turntable_outputs.hpp"

namespace lp::server {
namespace {

std::shared_ptr<TurntableJob> find_turntable(const App& app, const std::string& id) {
  auto job = std::dynamic_pointer_cast<TurntableJob>(app.turntables.find(id));
  if (!job) throw api::not_found("no turntable '" + api::excerpt(id) + "'");
  return job;
}

// The frames finished so far; 409 no_image_yet before the first.
std::vector<RenderImage> finished_frames(const TurntableJob& job) {
  auto frames = job.frames();
  if (frames.empty())
    throw api::ApiError(
        api::ErrorCode::NoImageYet,
        fmt::format("turntable '{}' is {} and has no finished frame yet", job.id(), enum_name(job.status())));
  return frames;
}

MemoryReservation reserve_frames(App& app, const TurntableJob& job, size_t frames, const std::string& what) {
  const auto& s = job.request().render.settings;
  const int64_t bytes = frames8_bytes(int64_t(frames), s.width, s.height) +
                        encode_bytes(ImageFormat::Png, int64_t(frames) * s.width, s.height);
  return app.memory.reserve(bytes, MemoryUse::Transient, what);
}

void submit(App& app, const httplib::Request& req, httplib::Response& res) {
  refuse_on_worker(app, "turntable");
  auto request = api::parse_turntable_request(api::parse_json_object(req.body), app.options.limits);
  const auto envmap = app.envmaps.find(request.render.envmap);
  if (!envmap)
    throw api::invalid_field("envmap",
                             "no environment map '" + api::excerpt(request.render.envmap) + "' is loaded");
  const int64_t triangles = resolve_meshes(request.render.scene, app);
  auto cameras = turntable_cameras(request);
  const auto& s = request.render.settings;
  auto memory = app.memory.reserve(
      turntable_bytes(request, triangles), MemoryUse::Transient,
      fmt::format("a turntable of {} frames of {}x{}", request.turntable.frames, s.width, s.height));
  auto job = std::make_shared<TurntableJob>(app.turntables.new_id(), std::move(request), std::move(cameras),
                                            envmap->map,
                                            TurntableJobContext{std::move(memory), &app.render_counters});
  const nlohmann::json status = job->status_json();
  if (!app.turntables.submit(job)) return send_queue_full(app.turntables, "turntables", res);
  send_accepted("/api/v1/turntables/" + job->id(), status, res);
}

void list(const App& app, httplib::Response& res) {
  nlohmann::json turntables = nlohmann::json::array();
  for (const auto& job : app.turntables.list()) turntables.push_back(job->status_json());
  send_json(res, {{"turntables", turntables},
                  {"running", app.turntables.running_count()},
                  {"queued", app.turntables.queued_count()}});
}

int frame_index(const TurntableJob& job, const std::string& text) {
  int index = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (error != std::errc() || end != text.data() + text.size() || index < 0 || index >= job.frame_count())
    throw api::not_found(fmt::format("turntable '{}' has frames 0 to {}, not '{}'", job.id(),
                                     job.frame_count() - 1, api::excerpt(text)));
  return index;
}

void frame(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_turntable(app, path_param(req, 1));
  const int index = frame_index(*job, path_param(req, 2));
  const auto params =
      api::parse_preview_params(req.params, ImageFormat::Png, job->request().render.tone_mapping);
  const auto size = api::parse_image_size(req.params);
  const auto frames = job->frames();
  if (size_t(index) >= frames.size())
    throw api::ApiError(api::ErrorCode::NoImageYet,
                        fmt::format("frame {} of turntable '{}' is not rendered yet ({} of {} done)", index,
                                    job->id(), frames.size(), job->frame_count()));
  const auto& settings = job->request().render.settings;
  const api::RenderImagePass color;
  auto memory = app.memory.reserve(api::render_picture_bytes(color, params, settings.width, settings.height,
                                                             settings.passes.list().size()),
                                   MemoryUse::Transient, "encoding a turntable frame");
  const RenderImage frame = fit_longest_side(frames[size_t(index)], size);
  send_reserved(res, api::encode_render_picture(pictures_of(frame, settings), color, params),
                format_mime_type(params.format), std::move(memory));
}

void zip(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_turntable(app, path_param(req, 1));
  const auto size = api::parse_image_size(req.params);
  const ToneMap tone = api::parse_tone_map(req.params, job->request().render.tone_mapping);
  const auto frames = finished_frames(*job);
  auto memory = reserve_frames(app, *job, frames.size(), "zipping a turntable's frames");
  const std::span<const render::Camera> cameras(job->cameras().data(), frames.size());
  send_reserved(res, frames_zip(frames8(frames, size, tone), api::describe_turntable_cameras(cameras)),
                "application/zip", std::move(memory));
}

void sheet(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_turntable(app, path_param(req, 1));
  const ImageFormat format = api::parse_eight_bit_format(req.params);
  const auto size = api::parse_image_size(req.params);
  const ToneMap tone = api::parse_tone_map(req.params, job->request().render.tone_mapping);
  const auto frames = finished_frames(*job);
  auto memory = reserve_frames(app, *job, frames.size(), "a turntable's contact sheet");
  send_reserved(res, frames_contact_sheet(frames, size, tone, format), format_mime_type(format),
                std::move(memory));
}

void animation(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_turntable(app, path_param(req, 1));
  const auto size = api::parse_image_size(req.params);
  const int fps = api::parse_animation_fps(req.params);
  const ToneMap tone = api::parse_tone_map(req.params, job->request().render.tone_mapping);
  const auto frames = finished_frames(*job);
  auto memory = reserve_frames(app, *job, frames.size(), "a turntable's animation");
  const Frames8 pictures = frames8(frames, size, tone);
  send_reserved(res, encode_webp_animation(pictures.pictures(), fps), format_mime_type(ImageFormat::Webp),
                std::move(memory));
}

void cancel(App& app, const httplib::Request& req, httplib::Response& res) {
  cancel_or_remove(app.turntables, *find_turntable(app, path_param(req, 1)), "turntable", res);
}

}  // namespace

void register_turntable_routes(Router& router, App& app) {
  const std::string root = "/api/v1/turntables";
  router.post(root, endpoint_of(app, submit));
  router.get(root, [&app](const httplib::Request&, httplib::Response& res) { list(app, res); });
  router.get(root + "/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    send_json(res, find_turntable(app, path_param(req, 1))->status_json());
  });
  router.del(root + "/{id}", endpoint_of(app, cancel));
  router.get(root + "/{id}/frames/{index}", endpoint_of(app, frame), Caching::Revalidate);
  router.get(root + "/{id}/frames.zip", endpoint_of(app, zip), Caching::Revalidate);
  router.get(root + "/{id}/contact-sheet", endpoint_of(app, sheet), Caching::Revalidate);
  router.get(root + "/{id}/animation.webp", endpoint_of(app, animation), Caching::Revalidate);
}

}  // namespace lp::server

// Prefiltered specular chains as jobs: POST /envmaps/{id}/prefilter queues one, or answers with the job
// that makes or made the same chain of the same map content (200, "reused": true); status, cancel /
// remove, the list, and the files of a finished chain. They run on a job manager of their own
// (App::prefilters), the same machinery as renders with its own queue.
#include <fmt/format.h>

#include <mutex>

#include "api/api_error.hpp"
#include "api/prefilter_files.hpp"
#include "api/prefilter_request.hpp"
#include "api/preview_params.hpp"
#include "engine/image/image_io.hpp"
#include "server/http/request_context.hpp"
#include "server/http/reserved_content.hpp"
#include "server/jobs/prefilter_job.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "server/routes/job_answers.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

std::string prefilter_url(const std::string& id) {
  return "/api/v1/prefilters/" + id;
}

std::shared_ptr<PrefilterJob> find_prefilter(const App& app, const std::string& id) {
  auto job = std::dynamic_pointer_cast<PrefilterJob>(app.prefilters.find(id));
  if (!job) throw api::not_found("no prefilter job '" + api::excerpt(id) + "'");
  return job;
}

// The job already making or holding this chain, if any.
std::shared_ptr<PrefilterJob> same_chain(const App& app, const std::string& fingerprint,
                                         const api::PrefilterRequest& request) {
  for (const auto& job : app.prefilters.list()) {
    auto prefilter = std::dynamic_pointer_cast<PrefilterJob>(job);
    if (prefilter && prefilter->answers(fingerprint, request)) return prefilter;
  }
  return nullptr;
}

// The memory of making a chain is reserved when its job starts; one that could never fit is refused now.
void check_fits(const MemoryBudget& memory, int64_t bytes) {
  if (bytes > memory.capacity())
    throw MemoryBudgetError(fmt::format("a prefiltered chain needs {} while it is made, more than the whole "
                                        "memory budget of {}",
                                        format_mib(bytes), format_mib(memory.capacity())),
                            false);
}

void submit(App& app, const httplib::Request& req, httplib::Response& res) {
  // One submission at a time, so two equal requests never both queue a job.
  static std::mutex submitting;
  const auto entry = app.envmaps.get(path_param(req, 1));
  auto request = api::parse_prefilter_request(req.body);
  const std::string fingerprint = envmap_content_hash(*entry->map);
  std::lock_guard lock(submitting);
  if (const auto job = same_chain(app, fingerprint, request)) {
    auto status = job->status_json();
    status["reused"] = true;
    res.set_header("Location", prefilter_url(job->id()));
    return send_json(res, status);
  }
  check_fits(app.memory, PrefilterJob::working_bytes(*entry->map, request));
  auto job = std::make_shared<PrefilterJob>(app.prefilters.new_id(), entry->name, entry->map, fingerprint,
                                            std::move(request), app.memory);
  auto status = job->status_json();  // taken before a runner can pick it up: "queued"
  status["reused"] = false;
  const std::string& client = current_request().client;
  switch (app.prefilters.submit(job, client)) {
    case JobManager::Admission::Accepted:
      return send_accepted(prefilter_url(job->id()), status, res);
    case JobManager::Admission::Refused:
      return send_queue_full(app.prefilters, "prefilters", res);
    case JobManager::Admission::ClientLimit:
      res.set_header("Retry-After", std::to_string(app.prefilters.retry_after_s()));
      return send_error(
          res, api::ErrorCode::TooManyJobs,
          fmt::format("client {} has {} prefilter jobs queued or running, the limit per client "
                      "(--{}); retry when one has ended",
                      client, app.prefilters.client_count(client), kMaxPrefiltersPerClient.flag));
  }
}

void list(const App& app, httplib::Response& res) {
  nlohmann::json jobs = nlohmann::json::array();
  for (const auto& job : app.prefilters.list()) jobs.push_back(job->status_json());
  send_json(res, {{"prefilters", jobs},
                  {"running", app.prefilters.running_count()},
                  {"queued", app.prefilters.queued_count()}});
}

std::shared_ptr<const PrefilteredChain> finished_chain(const PrefilterJob& job) {
  auto chain = job.chain();
  if (!chain)
    throw api::ApiError(api::ErrorCode::NoImageYet, fmt::format("prefilter '{}' is {} and has no chain yet",
                                                                job.id(), enum_name(job.status())));
  return chain;
}

// A target's file, written when the job finished.
void target_file(App& app, const PrefilterJob& job, const std::string& name, httplib::Response& res) {
  const auto files = job.target_files();
  if (!files)
    throw api::ApiError(api::ErrorCode::NoImageYet, fmt::format("prefilter '{}' is {} and has no files yet",
                                                                job.id(), enum_name(job.status())));
  for (const api::BakeFile& f : *files) {
    if (f.name != name) continue;
    auto memory = app.memory.reserve(int64_t(f.bytes.size()), MemoryUse::Transient, "sending " + name);
    return send_reserved(res, std::vector<uint8_t>(f.bytes), f.content_type, std::move(memory));
  }
  throw api::not_found("no file '" + api::excerpt(name) + "' in this job's files");
}

void file(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_prefilter(app, path_param(req, 1));
  const std::string name = path_param(req, 2);
  if (job->request().target) return target_file(app, *job, name, res);
  const int64_t bytes = api::prefilter_file_bytes(job->request(), name);  // 404 for an unknown name
  const auto chain = finished_chain(*job);
  auto memory = app.memory.reserve(bytes, MemoryUse::Transient, "encoding " + name);
  send_reserved(res, api::encode_prefilter_file(*chain, job->request(), name),
                api::prefilter_file_mime_type(job->request().format), std::move(memory));
}

// A level tone mapped to PNG, to be looked at (the files hold the values).
void level_png(App& app, const httplib::Request& req, httplib::Response& res) {
  const auto job = find_prefilter(app, path_param(req, 1));
  const int level = api::prefilter_level_index(job->request(), path_param(req, 2));
  const ToneMap tone = api::parse_tone_map(req.params);
  const auto chain = finished_chain(*job);
  const Image& image = chain->levels[size_t(level)];
  const int64_t drawing = int64_t(image.width()) * image.height() * 3;
  send_png_picture(res, app.memory, image.width(), image.height(), drawing, "a prefiltered level picture",
                   [&] { return tone_map_rgb8(image, tone); });
}

}  // namespace

void register_prefilter_routes(Router& router, App& app) {
  router.post("/api/v1/envmaps/{id}/prefilter", endpoint_of(app, submit));
  router.get("/api/v1/prefilters",
             [&app](const httplib::Request&, httplib::Response& res) { list(app, res); });
  router.get("/api/v1/prefilters/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    send_json(res, find_prefilter(app, path_param(req, 1))->status_json());
  });
  router.get("/api/v1/prefilters/{id}/files/{name}", endpoint_of(app, file), Caching::Revalidate);
  router.get("/api/v1/prefilters/{id}/levels/{n}.png", endpoint_of(app, level_png), Caching::Revalidate);
  router.del("/api/v1/prefilters/{id}", [&app](const httplib::Request& req, httplib::Response& res) {
    cancel_or_remove(app.prefilters, *find_prefilter(app, path_param(req, 1)), "prefilter job", res);
  });
}

}  // namespace lp::server

#include "server/routes/job_answers.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "server/app.hpp"
#include "server/http/responses.hpp"

namespace lp::server {

void refuse_on_worker(const App& app, const std::string& kind) {
  if (app.options.scale_out.role == ServerRole::Worker)
    throw api::ApiError(
        api::ErrorCode::WorkerOnly,
        fmt::format("this server runs with --role worker: it renders work items of other servers' "
                    "renders and takes no {} of its own; send it to a server with --role api or "
                    "both",
                    kind));
}

void send_queue_full(const JobManager& jobs, const std::string& kind, httplib::Response& res) {
  res.set_header("Retry-After", std::to_string(jobs.retry_after_s()));
  send_error(res, api::ErrorCode::QueueFull,
             fmt::format("{} {} are running and {} queued (the limit); retry later", jobs.running_count(),
                         kind, jobs.queued_count()));
}

void send_accepted(const std::string& location, const nlohmann::json& status, httplib::Response& res) {
  res.set_header("Location", location);
  send_json(res, status, 202);
}

void cancel_or_remove(JobManager& jobs, const Job& job, const std::string& kind, httplib::Response& res) {
  switch (jobs.cancel_or_remove(job.id())) {
    case JobManager::CancelOutcome::NotFound:
      throw api::not_found("no " + kind + " '" + job.id() + "'");
    case JobManager::CancelOutcome::Removed:
      res.status = 204;
      return;
    default:
      send_json(res, job.status_json(), 202);
  }
}

}  // namespace lp::server

#pragma once
// The answers the routes of every kind of background job (renders, prefilters) give alike.
#include <httplib.h>

#include <nlohmann/json.hpp>
#include <string>

#include "server/jobs/job.hpp"
#include "server/jobs/job_manager.hpp"

namespace lp::server {

struct App;

// 409 worker_only on a server with --role worker: it renders the work items of other servers' renders
// and takes no `kind` job ("render", "turntable") of its own.
void refuse_on_worker(const App& app, const std::string& kind);
// 503 queue_full with Retry-After: `kind` ("renders") are running and queued up to the limit.
void send_queue_full(const JobManager& jobs, const std::string& kind, httplib::Response& res);
// 202 with the job's status (taken before a runner could pick it up) and its URL as Location.
void send_accepted(const std::string& location, const nlohmann::json& status, httplib::Response& res);
// DELETE of a job: a queued or running job is cancelled (202 with its status), a finished one removed
// (204). `kind` names it in a 404 ("render job").
void cancel_or_remove(JobManager& jobs, const Job& job, const std::string& kind, httplib::Response& res);

}  // namespace lp::server

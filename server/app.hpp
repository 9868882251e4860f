#pragma once
// Everything the handlers share: the options and the registries.
#include "server/envmap_registry.hpp"
#include "server/job_manager.hpp"
#include "server/options.hpp"

namespace lp::server {

inline JobManagerConfig render_job_config(const Options& o) {
  return {o.max_running_jobs, o.max_queued_jobs, o.max_finished_jobs, o.max_finished_mb << 20, o.threads};
}

struct App {
  Options options;
  EnvMapRegistry envmaps;
  JobManager renders;  // declared last: destroyed first, cancelling and joining the render jobs

  explicit App(Options opts)
      : options(std::move(opts)), envmaps(options.max_envmaps), renders(render_job_config(options)) {}
};

}  // namespace lp::server

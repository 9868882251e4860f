#pragma once
// How many background jobs of a kind run and wait at once (in all, and of one client), how many finished
// ones are kept with their results, and at what priority their threads run. The flags of the render jobs'
// numbers, and of the prefilter jobs' per client, are declared here.
#include <cstdint>

#include "api/parameters.hpp"
#include "server/jobs/thread_priority.hpp"

namespace lp::server {

inline constexpr api::IntParameter kMaxRunningJobs{
    "max-running-jobs", 2, {1, 256}, "renders running at once, each in its own thread arena"};
inline constexpr api::IntParameter kMaxQueuedJobs{
    "max-queued-jobs", 16, {0, 1 << 20}, "renders waiting to run; a full queue answers 503"};
inline constexpr api::IntParameter kMaxPrefiltersPerClient{
    "max-prefilters-per-client",
    4,
    {1, 1 << 20},
    "prefilter jobs one client may have queued or running; more are refused with 429"};
inline constexpr api::IntParameter kMaxFinishedJobs{
    "max-finished-jobs", 64, {1, 1 << 20}, "finished renders kept with their images, oldest dropped"};
inline constexpr api::IntParameter kMaxFinishedMb{
    "max-finished-mb", 1024, {1, 1 << 24}, "MiB of images kept by finished renders, oldest dropped"};

struct JobManagerConfig {
  int max_running = int(kMaxRunningJobs.fallback);  // runner threads = jobs running at once
  int max_queued = int(kMaxQueuedJobs.fallback);    // jobs waiting for a runner (beyond the idle runners)
  // Jobs one client may have queued or running (0: no bound but the queue's): the prefilters' flag.
  int max_per_client = int(kMaxPrefiltersPerClient.fallback);
  int max_finished = int(kMaxFinishedJobs.fallback);           // finished jobs kept
  int64_t max_finished_bytes = kMaxFinishedMb.fallback << 20;  // and the results they keep
  int arena_concurrency = 0;                                   // threads per job arena; 0 = all cores
  RenderPriority render_priority = RenderPriority::Low;        // of the threads that render
};

}  // namespace lp::server

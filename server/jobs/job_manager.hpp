#pragma once
// Runs background jobs: a bounded FIFO queue, a fixed number of runner threads, each running one job at a
// time inside its own tbb::task_arena (so concurrent jobs share the cores fairly: oneTBB divides its
// workers between the arenas, and the runners only wait: job_arena.hpp), and a bounded list of finished
// jobs kept for their results (oldest dropped). Thread-safe. The destructor cancels every job and joins the
// runners.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/jobs/job.hpp"
#include "server/jobs/job_manager_config.hpp"

namespace lp::server {

class JobManager {
 public:
  explicit JobManager(const JobManagerConfig& config);
  ~JobManager();
  JobManager(const JobManager&) = delete;
  JobManager& operator=(const JobManager&) = delete;

  // A fresh random id (16 hex digits).
  std::string new_id();

  enum class Admission { Accepted, Refused, ClientLimit };
  // Queues the job; Refused if max_running + max_queued jobs are already queued or running, or the
  // manager is shutting down; ClientLimit if max_per_client jobs of `client` (a request's client as the
  // transport names it; empty: none) are. A job with the id of an ended job replaces it (a resumed run).
  Admission submit(std::shared_ptr<Job> job, const std::string& client);
  bool submit(std::shared_ptr<Job> job) { return submit(std::move(job), "") == Admission::Accepted; }
  // Adds a job that ended in an earlier run of the server (restored from the state directory).
  void restore(std::shared_ptr<Job> job);

  std::shared_ptr<Job> find(const std::string& id) const;  // nullptr if unknown (or dropped)
  std::vector<std::shared_ptr<Job>> list() const;          // oldest first

  enum class CancelOutcome { NotFound, Cancelled, Cancelling, Removed };
  // A queued job is cancelled at once, a running one is asked to stop (it stops at its next check),
  // a finished one is removed.
  CancelOutcome cancel_or_remove(const std::string& id);

  // Seconds a client should wait before retrying a full queue: an estimate of when the running job
  // closest to the end finishes, clamped to [1, 60].
  int retry_after_s() const;

  // Refuses later submissions, interrupts the queued jobs, asks the running ones to stop at their next
  // safe point, halts those still running after `grace`, and joins the runners. Idempotent.
  void shutdown(std::chrono::milliseconds grace = {});

  int queued_count() const;
  int running_count() const;
  int client_count(const std::string& client) const;  // jobs of `client` queued or running

 private:
  void runner_loop(int runner);
  void retire(const std::shared_ptr<Job>& job);         // adds to the finished list and drops the oldest
  void drop_finished(const std::shared_ptr<Job>& job);  // takes an ended job out of the finished list
  void forget(const std::shared_ptr<Job>& job);         // and lets it delete what it keeps
  std::shared_ptr<Job> next_job();                      // blocks; nullptr when stopping
  int client_count_locked(const std::string& client) const;

  const JobManagerConfig config_;
  mutable std::mutex mutex_;
  std::condition_variable work_cv_;
  bool stopping_ = false;
  std::map<std::string, std::shared_ptr<Job>> jobs_;  // all known jobs, by id
  std::deque<std::shared_ptr<Job>> queue_;
  std::vector<std::shared_ptr<Job>> running_;
  std::map<std::string, std::string> clients_;  // the client of each job queued or running, by job id
  std::deque<std::shared_ptr<Job>> finished_;   // oldest first
  int64_t finished_bytes_ = 0;
  uint64_t id_state_;
  std::vector<std::jthread> runners_;
};

}  // namespace lp::server

#pragma once
// A background job run by the JobManager: work that reports progress in units and can be cancelled.
// This is the generic part (status, timing, progress, cancellation, error); a subclass (RenderJob) does
// the work in run() and adds its own fields to the status JSON.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace lp::server {

enum class JobStatus { Queued, Running, Done, Failed, Cancelled };

const char* status_name(JobStatus status);  // "queued", "running", ...
bool is_finished(JobStatus status);         // done, failed or cancelled

struct JobError {
  std::string code;  // like the API error codes: "invalid_argument", "not_found", "internal", ...
  std::string message;
};

class Job {
 public:
  explicit Job(std::string id);
  virtual ~Job() = default;
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;

  const std::string& id() const { return id_; }
  JobStatus status() const;
  bool cancel_requested() const { return cancel_.load(); }
  double progress() const;   // 0..1: work units done / total (1 when done)
  double elapsed_s() const;  // since the job started running (0 while queued; frozen once finished)
  std::optional<JobError> error() const;
  std::chrono::system_clock::time_point created() const { return created_; }

  // {"id","status","progress","elapsed_s","error","created"} plus the subclass's fields.
  nlohmann::json status_json() const;

  // Blocks until the job has finished or `timeout` has passed; true if finished.
  bool wait_finished_for(std::chrono::milliseconds timeout) const;

  // Memory the job keeps once finished (its result), so the manager can bound what it retains.
  virtual int64_t retained_bytes() const { return 0; }

 protected:
  // Does the work on a runner thread, inside the job's task arena. Returns true when all the work was
  // done, false when it stopped early because cancel_flag() became true. Throws lp::Error (or any
  // std::exception) to fail the job.
  virtual bool run() = 0;
  virtual void describe(nlohmann::json& out) const = 0;

  const std::atomic<bool>& cancel_flag() const { return cancel_; }
  void set_work_total(int64_t units) { work_total_.store(units); }
  void add_work_done(int64_t units) { work_done_.fetch_add(units, std::memory_order_relaxed); }

 private:
  friend class JobManager;
  // Queued -> cancelled at once (true); a running job only gets the flag and stops at its next check.
  bool request_cancel();
  // Runs the job to a final status; never throws.
  void execute();
  bool start();  // queued -> running; false if it was cancelled meanwhile
  void finish(JobStatus status, std::optional<JobError> error);

  const std::string id_;
  const std::chrono::system_clock::time_point created_;
  std::atomic<bool> cancel_{false};
  std::atomic<int64_t> work_total_{0};
  std::atomic<int64_t> work_done_{0};

  mutable std::mutex mutex_;
  mutable std::condition_variable finished_cv_;
  JobStatus status_ = JobStatus::Queued;
  std::optional<std::chrono::steady_clock::time_point> started_, ended_;
  std::optional<JobError> error_;
};

}  // namespace lp::server

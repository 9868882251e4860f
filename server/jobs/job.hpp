#pragma once
// A background job run by the JobManager: work that reports progress in units and can be cancelled.
// This is the generic part (status, timing, progress, cancellation, error); a subclass (RenderJob) does
// the work in run() and adds its own fields to the status JSON.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "api/error_codes.hpp"
#include "engine/core/enum_table.hpp"

namespace lp::server {

// Interrupted: stopped by a shutdown (or found unfinished after a crash); it can be resumed as a new run.
enum class JobStatus { Queued, Running, Done, Failed, Cancelled, Interrupted };

constexpr auto enum_entries(JobStatus) {
  return std::to_array<EnumEntry<JobStatus>>({{JobStatus::Queued, "queued"},
                                              {JobStatus::Running, "running"},
                                              {JobStatus::Done, "done"},
                                              {JobStatus::Failed, "failed"},
                                              {JobStatus::Cancelled, "cancelled"},
                                              {JobStatus::Interrupted, "interrupted"}});
}
bool is_finished(JobStatus status);  // done, failed, cancelled or interrupted

struct JobError {
  std::string code;  // a name of api/error_codes.hpp ("corrupt", "not_found", "internal", ...)
  std::string message;
};

class Job {
 public:
  // `created` and `earlier_elapsed_s` carry over from an earlier run when the job continues one.
  explicit Job(std::string id,
               std::chrono::system_clock::time_point created = std::chrono::system_clock::now(),
               double earlier_elapsed_s = 0);
  virtual ~Job() = default;
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;

  const std::string& id() const { return id_; }
  JobStatus status() const;
  bool cancel_requested() const { return stop_.load() == StopRequest::Cancel; }
  double progress() const;   // 0..1: work units done / total (1 when done)
  double elapsed_s() const;  // running time, earlier runs included (frozen once finished)
  std::optional<JobError> error() const;
  std::chrono::system_clock::time_point created() const { return created_; }

  // {"id","status","progress","elapsed_s","error","created"} plus the subclass's fields.
  nlohmann::json status_json() const;

  // Blocks until the job has finished or `timeout` has passed; true if finished.
  bool wait_finished_for(std::chrono::milliseconds timeout) const;

  // Memory the job keeps once finished (its result), so the manager can bound what it retains.
  virtual int64_t retained_bytes() const { return 0; }

  // Sets the final status of a job restored from an earlier run, before it is handed to the manager.
  void restore_ended(JobStatus status, std::optional<JobError> error);

 protected:
  // Called once with the job's final status, just before others can see it (from the thread that sets it).
  virtual void ending(JobStatus, const std::optional<JobError>&) {}
  // Called when the manager drops the job (removed by a client, or beyond the finished-job limits).
  virtual void forgotten() {}
  // A shutdown asked the job to stop at its next safe point (a pass boundary) and become interrupted.
  bool interrupt_requested() const { return stop_.load() == StopRequest::Interrupt; }

  // Does the work on a worker of the job's task arena (its runner thread waits). Returns true when all the
  // work was done, false when it stopped early because cancel_flag() became true. Throws lp::Error (or any
  // std::exception) to fail the job.
  virtual bool run() = 0;
  virtual void describe(nlohmann::json& out) const = 0;

  // Checked by the work at every step: set by a cancel, or when a shutdown's grace period ends.
  const std::atomic<bool>& cancel_flag() const { return halt_; }
  void set_work(int64_t total, int64_t done) {
    work_total_.store(total);
    work_done_.store(done);
  }
  void add_work_done(int64_t units) { work_done_.fetch_add(units, std::memory_order_relaxed); }

 private:
  friend class JobManager;
  enum class StopRequest { None, Cancel, Interrupt };

  // Queued -> cancelled at once (true); a running job only gets the flag and stops at its next check.
  bool request_cancel();
  // Queued -> interrupted at once (true); a running job stops at its next safe point.
  bool request_interrupt();
  void halt() { halt_.store(true); }  // stop at the next check, safe point or not
  // Runs the job to a final status; never throws.
  void execute();
  bool start();  // queued -> running; false if it was cancelled meanwhile
  void finish(JobStatus status, std::optional<JobError> error);
  void failed(api::ErrorCode code, const std::string& message);
  // Queued -> `status` (true); otherwise nothing.
  bool end_if_queued(JobStatus status);

  const std::string id_;
  const std::chrono::system_clock::time_point created_;
  const double earlier_elapsed_s_;
  std::atomic<StopRequest> stop_{StopRequest::None};
  std::atomic<bool> halt_{false};
  std::atomic<int64_t> work_total_{0};
  std::atomic<int64_t> work_done_{0};

  mutable std::mutex mutex_;
  mutable std::condition_variable finished_cv_;
  JobStatus status_ = JobStatus::Queued;
  std::optional<std::chrono::steady_clock::time_point> started_, ended_;
  std::optional<JobError> error_;
};

}  // namespace lp::server

#include "server/jobs/job.hpp"

#include <algorithm>
#include <ctime>
#include <exception>

#include "api/api_error.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory_budget.hpp"

namespace lp::server {
namespace {

std::string iso8601(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace

bool is_finished(JobStatus status) {
  return status != JobStatus::Queued && status != JobStatus::Running;
}

Job::Job(std::string id, std::chrono::system_clock::time_point created, double earlier_elapsed_s)
    : id_(std::move(id)), created_(created), earlier_elapsed_s_(earlier_elapsed_s) {}

JobStatus Job::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

double Job::progress() const {
  if (status() == JobStatus::Done) return 1.0;
  const int64_t total = work_total_.load();
  if (total <= 0) return 0.0;
  return std::clamp(static_cast<double>(work_done_.load()) / static_cast<double>(total), 0.0, 1.0);
}

double Job::elapsed_s() const {
  std::lock_guard lock(mutex_);
  if (!started_) return earlier_elapsed_s_;
  const auto end = ended_.value_or(std::chrono::steady_clock::now());
  return earlier_elapsed_s_ + std::chrono::duration<double>(end - *started_).count();
}

std::optional<JobError> Job::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

nlohmann::json Job::status_json() const {
  nlohmann::json out;
  out["id"] = id_;
  out["status"] = enum_name(status());
  out["progress"] = progress();
  out["elapsed_s"] = elapsed_s();
  out["created"] = iso8601(created_);
  out["cancel_requested"] = cancel_requested();
  const auto err = error();
  out["error"] =
      err ? nlohmann::json{{"code", err->code}, {"message", err->message}} : nlohmann::json(nullptr);
  describe(out);
  return out;
}

bool Job::wait_finished_for(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return finished_cv_.wait_for(lock, timeout, [&] { return is_finished(status_); });
}

void Job::restore_ended(JobStatus status, std::optional<JobError> error) {
  std::lock_guard lock(mutex_);
  status_ = status;
  error_ = std::move(error);
}

bool Job::end_if_queued(JobStatus status) {
  {
    std::lock_guard lock(mutex_);
    if (status_ != JobStatus::Queued) return false;
    status_ = status;
  }
  ending(status, std::nullopt);
  finished_cv_.notify_all();
  return true;
}

bool Job::request_cancel() {
  stop_.store(StopRequest::Cancel);
  halt_.store(true);
  return end_if_queued(JobStatus::Cancelled);
}

bool Job::request_interrupt() {
  auto expected = StopRequest::None;
  stop_.compare_exchange_strong(expected, StopRequest::Interrupt);
  return end_if_queued(JobStatus::Interrupted);
}

bool Job::start() {
  std::lock_guard lock(mutex_);
  if (status_ != JobStatus::Queued) return false;
  status_ = JobStatus::Running;
  started_ = std::chrono::steady_clock::now();
  return true;
}

void Job::finish(JobStatus status, std::optional<JobError> error) {
  ending(status, error);
  {
    std::lock_guard lock(mutex_);
    status_ = status;
    error_ = std::move(error);
    ended_ = std::chrono::steady_clock::now();
  }
  finished_cv_.notify_all();
}

void Job::failed(api::ErrorCode code, const std::string& message) {
  finish(JobStatus::Failed, JobError{std::string(api::code_name(code)), message});
}

void Job::execute() {
  if (!start()) return;
  try {
    const bool completed = run();
    const bool interrupted = stop_.load() == StopRequest::Interrupt;
    finish(completed     ? JobStatus::Done
           : interrupted ? JobStatus::Interrupted
                         : JobStatus::Cancelled,
           std::nullopt);
  } catch (const MemoryBudgetError& e) {
    failed(e.transient() ? api::ErrorCode::MemoryBusy : api::ErrorCode::InsufficientMemory, e.what());
  } catch (const Error& e) {
    failed(api::error_code_for(e.kind()), e.what());
  } catch (const api::ApiError& e) {
    failed(e.code(), e.what());
  } catch (const std::exception& e) {
    failed(api::ErrorCode::Internal, e.what());
  } catch (...) {
    failed(api::ErrorCode::Internal, "unknown error");
  }
}

}  // namespace lp::server

#include "server/jobs/job_manager.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/core/rng.hpp"
#include "server/jobs/job_arena.hpp"

namespace lp::server {

JobManager::JobManager(const JobManagerConfig& config) : config_(config), id_state_(std::random_device{}()) {
  id_state_ = (id_state_ << 32) ^ std::random_device{}();
  for (int i = 0; i < std::max(1, config_.max_running); ++i)
    runners_.emplace_back([this, i] { runner_loop(i); });
}

JobManager::~JobManager() {
  shutdown();
}

std::string JobManager::new_id() {
  std::lock_guard lock(mutex_);
  id_state_ += 0x9e3779b97f4a7c15ULL;
  return fmt::format("{:016x}", mix64(id_state_));
}

JobManager::Admission JobManager::submit(std::shared_ptr<Job> job, const std::string& client) {
  {
    std::lock_guard lock(mutex_);
    // Capacity counts running jobs too, so a job is accepted whenever a runner is idle, and the
    // answer does not depend on whether a runner has taken the previous job off the queue yet.
    if (stopping_ || queue_.size() + running_.size() >= size_t(config_.max_queued + config_.max_running))
      return Admission::Refused;
    if (!client.empty() && config_.max_per_client > 0 &&
        client_count_locked(client) >= config_.max_per_client)
      return Admission::ClientLimit;
    if (auto it = jobs_.find(job->id()); it != jobs_.end()) {
      if (!is_finished(it->second->status())) return Admission::Refused;
      drop_finished(it->second);
    }
    jobs_[job->id()] = job;
    if (!client.empty()) clients_[job->id()] = client;
    queue_.push_back(std::move(job));
  }
  work_cv_.notify_one();
  return Admission::Accepted;
}

void JobManager::restore(std::shared_ptr<Job> job) {
  std::lock_guard lock(mutex_);
  jobs_[job->id()] = job;
  // Interrupted jobs wait for a resume and are not subject to the finished-job limits.
  if (job->status() != JobStatus::Interrupted) retire(job);
}

std::shared_ptr<Job> JobManager::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : it->second;
}

std::vector<std::shared_ptr<Job>> JobManager::list() const {
  std::vector<std::shared_ptr<Job>> out;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [id, job] : jobs_) out.push_back(job);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a->created() < b->created(); });
  return out;
}

JobManager::CancelOutcome JobManager::cancel_or_remove(const std::string& id) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(id);
    if (it == jobs_.end()) return CancelOutcome::NotFound;
    job = it->second;
    if (is_finished(job->status())) {
      jobs_.erase(it);
      forget(job);
      return CancelOutcome::Removed;
    }
  }
  if (!job->request_cancel()) return CancelOutcome::Cancelling;  // running: stops at its next tile
  spdlog::info("job {} cancelled while queued", id);
  std::lock_guard lock(mutex_);
  auto q = std::find(queue_.begin(), queue_.end(), job);
  if (q != queue_.end()) {
    queue_.erase(q);
    retire(job);
  }
  // else a runner took it off the queue just now; it sees the cancelled status and retires it.
  return CancelOutcome::Cancelled;
}

int JobManager::retry_after_s() const {
  std::lock_guard lock(mutex_);
  if (running_.empty()) return 1;
  double soonest = 60;
  for (const auto& job : running_) {
    const double p = job->progress();
    if (p > 0.01) soonest = std::min(soonest, job->elapsed_s() * (1 - p) / p);
  }
  return std::clamp(int(std::ceil(soonest)), 1, 60);
}

int JobManager::queued_count() const {
  std::lock_guard lock(mutex_);
  return int(queue_.size());
}

int JobManager::running_count() const {
  std::lock_guard lock(mutex_);
  return int(running_.size());
}

int JobManager::client_count(const std::string& client) const {
  std::lock_guard lock(mutex_);
  return client_count_locked(client);
}

int JobManager::client_count_locked(const std::string& client) const {
  return int(
      std::count_if(clients_.begin(), clients_.end(), [&](const auto& c) { return c.second == client; }));
}

void JobManager::shutdown(std::chrono::milliseconds grace) {
  std::vector<std::shared_ptr<Job>> queued, running;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
    queued.assign(queue_.begin(), queue_.end());
    running = running_;
    queue_.clear();
  }
  work_cv_.notify_all();
  if (!queued.empty() || !running.empty())
    spdlog::info("shutting down: interrupting {} queued and {} running job(s), {} ms grace", queued.size(),
                 running.size(), grace.count());
  for (const auto& job : queued) job->request_interrupt();
  for (const auto& job : running) job->request_interrupt();
  const auto deadline = std::chrono::steady_clock::now() + grace;
  for (const auto& job : running) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (job->wait_finished_for(std::max(left, std::chrono::milliseconds(0)))) continue;
    spdlog::warn("job {} did not reach the end of a pass within the grace period: halting it", job->id());
    job->halt();
  }
  runners_.clear();  // joins
}

std::shared_ptr<Job> JobManager::next_job() {
  std::unique_lock lock(mutex_);
  work_cv_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
  if (stopping_) return nullptr;
  auto job = std::move(queue_.front());
  queue_.pop_front();
  running_.push_back(job);
  return job;
}

void JobManager::runner_loop(int runner) {
  JobArena arena(config_.arena_concurrency, config_.render_priority);
  while (auto job = next_job()) {
    spdlog::debug("runner {} takes job {}", runner, job->id());
    arena.execute([&] { job->execute(); });
    std::lock_guard lock(mutex_);
    running_.erase(std::find(running_.begin(), running_.end(), job));
    retire(job);
  }
}

void JobManager::retire(const std::shared_ptr<Job>& job) {
  clients_.erase(job->id());
  if (!jobs_.count(job->id())) return;  // removed by a DELETE between its end and now
  if (stopping_ && job->status() == JobStatus::Interrupted) return;  // kept for a resume after the restart
  finished_.push_back(job);
  finished_bytes_ += job->retained_bytes();
  while (finished_.size() > 1 &&
         (int(finished_.size()) > config_.max_finished || finished_bytes_ > config_.max_finished_bytes)) {
    const auto oldest = finished_.front();
    jobs_.erase(oldest->id());
    forget(oldest);
    spdlog::debug("dropped finished job {} (finished-job limit)", oldest->id());
  }
}

void JobManager::drop_finished(const std::shared_ptr<Job>& job) {
  auto f = std::find(finished_.begin(), finished_.end(), job);
  if (f == finished_.end()) return;
  finished_bytes_ -= job->retained_bytes();
  finished_.erase(f);
}

void JobManager::forget(const std::shared_ptr<Job>& job) {
  drop_finished(job);
  job->forgotten();
}

}  // namespace lp::server

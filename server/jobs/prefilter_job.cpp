#include "server/jobs/prefilter_job.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <thread>

#include "api/prefilter_schema.hpp"

namespace lp::server {

PrefilterJob::PrefilterJob(std::string id, std::string envmap_name, std::shared_ptr<const EnvMap> envmap,
                           std::string envmap_fingerprint, api::PrefilterRequest request, MemoryBudget budget)
    : Job(std::move(id)),
      envmap_name_(std::move(envmap_name)),
      envmap_fingerprint_(std::move(envmap_fingerprint)),
      request_(std::move(request)),
      envmap_(std::move(envmap)),
      budget_(std::move(budget)) {
  set_work(prefilter_work_units(request_.params), 0);
}

int64_t PrefilterJob::working_bytes(const EnvMap& map, const api::PrefilterRequest& request) {
  return prefilter_working_bytes(map.width(), map.height(), request.params);
}

MemoryReservation PrefilterJob::reserve_working_memory() const {
  const auto& p = request_.params;
  const std::string what =
      fmt::format("a prefiltered chain of {} levels from {} texels wide", p.levels, p.base_size);
  for (bool logged = false;; logged = true) {
    try {
      return budget_.reserve(working_bytes(*envmap_, request_), MemoryUse::Transient, what);
    } catch (const MemoryBudgetError& e) {
      if (!e.transient()) throw;
      if (!logged) spdlog::info("prefilter {} waits for memory: {}", id(), e.what());
    }
    if (cancel_flag().load() || interrupt_requested()) return {};
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

std::shared_ptr<const PrefilteredChain> PrefilterJob::chain() const {
  std::lock_guard lock(mutex_);
  return chain_;
}

bool PrefilterJob::answers(const std::string& envmap_fingerprint,
                           const api::PrefilterRequest& request) const {
  if (envmap_fingerprint != envmap_fingerprint_ || !(request == request_) || cancel_requested()) return false;
  const JobStatus s = status();
  return s == JobStatus::Queued || s == JobStatus::Running || s == JobStatus::Done;
}

int64_t PrefilterJob::retained_bytes() const {
  return chain() ? prefiltered_chain_bytes(request_.params) : 0;
}

bool PrefilterJob::run() {
  memory_ = reserve_working_memory();
  if (!memory_) return false;  // stopped while it waited
  const auto& p = request_.params;
  spdlog::info("prefilter {} started: map '{}', {} levels from {} texels wide, {} samples", id(),
               envmap_name_, p.levels, p.base_size, p.samples);
  const PrefilterControl control{[this] { return cancel_flag().load() || interrupt_requested(); },
                                 [this](int64_t units) { add_work_done(units); }};
  auto chain = prefilter_chain(*envmap_, p, control);
  spdlog::info("prefilter {} {} after {:.2f} s", id(), chain ? "done" : "stopped", elapsed_s());
  if (!chain) return false;
  std::lock_guard lock(mutex_);
  chain_ = std::make_shared<const PrefilteredChain>(std::move(*chain));
  return true;
}

void PrefilterJob::describe(nlohmann::json& out) const {
  const auto done = chain();
  api::describe_prefilter(out, request_,
                          {envmap_name_, "/api/v1/prefilters/" + id() + "/files", done != nullptr,
                           done ? done->source_width : 0});
}

void PrefilterJob::ending(JobStatus, const std::optional<JobError>&) {
  envmap_.reset();
  memory_.resize(std::min(memory_.bytes(), retained_bytes()));
  memory_.set_use(MemoryUse::Held);
}

}  // namespace lp::server

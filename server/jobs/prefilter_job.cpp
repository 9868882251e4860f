#include "server/jobs/prefilter_job.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <thread>

#include "api/bake/bake_request.hpp"
#include "api/prefilter_schema.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::server {

PrefilterJob::PrefilterJob(std::string id, std::string envmap_name, std::shared_ptr<const EnvMap> envmap,
                           std::string envmap_fingerprint, api::PrefilterRequest request, MemoryBudget budget)
    : Job(std::move(id)),
      envmap_name_(std::move(envmap_name)),
      envmap_fingerprint_(std::move(envmap_fingerprint)),
      request_(std::move(request)),
      envmap_(std::move(envmap)),
      budget_(std::move(budget)) {
  set_work(api::makes_chain(request_) ? prefilter_work_units(request_.params) : 1, 0);
}

int64_t PrefilterJob::working_bytes(const EnvMap& map, const api::PrefilterRequest& request) {
  return api::makes_chain(request) ? prefilter_working_bytes(map.width(), map.height(), request.params) : 0;
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

std::shared_ptr<const std::vector<api::BakeFile>> PrefilterJob::target_files() const {
  std::lock_guard lock(mutex_);
  return target_files_;
}

int64_t PrefilterJob::retained_bytes() const {
  const auto files = target_files();
  return (chain() ? prefiltered_chain_bytes(request_.params) : 0) +
         (files ? api::bake_files_bytes(*files) : 0);
}

std::shared_ptr<const std::vector<api::BakeFile>> PrefilterJob::write_target_files(
    const PrefilteredChain* chain) {
  if (!request_.target) return nullptr;
  const auto sh = sh_projection_cached(*envmap_)->radiance.truncated(api::kBakeShBands);
  const api::BakeInput input{envmap_name_, *envmap_, chain, sh, request_};
  auto files =
      std::make_shared<const std::vector<api::BakeFile>>(api::target_spec(*request_.target).write(input));
  memory_.resize(memory_.bytes() + api::bake_files_bytes(*files));
  return files;
}

bool PrefilterJob::run() {
  memory_ = reserve_working_memory();
  if (!memory_) return false;  // stopped while it waited
  const auto& p = request_.params;
  spdlog::info("prefilter {} started: map '{}', {} levels from {} texels wide, {} samples", id(),
               envmap_name_, p.levels, p.base_size, p.samples);
  const PrefilterControl control{[this] { return cancel_flag().load() || interrupt_requested(); },
                                 [this](int64_t units) { add_work_done(units); }};
  std::shared_ptr<const PrefilteredChain> chain;
  if (api::makes_chain(request_)) {
    auto made = prefilter_chain(*envmap_, p, control);
    if (!made) {
      spdlog::info("prefilter {} stopped after {:.2f} s", id(), elapsed_s());
      return false;
    }
    chain = std::make_shared<const PrefilteredChain>(std::move(*made));
  } else {
    add_work_done(1);
  }
  auto files = write_target_files(chain.get());
  spdlog::info("prefilter {} done after {:.2f} s", id(), elapsed_s());
  std::lock_guard lock(mutex_);
  chain_ = std::move(chain);
  target_files_ = std::move(files);
  done_ = true;
  return true;
}

void PrefilterJob::describe(nlohmann::json& out) const {
  std::shared_ptr<const PrefilteredChain> done_chain;
  std::shared_ptr<const std::vector<api::BakeFile>> files;
  bool done = false;
  {
    std::lock_guard lock(mutex_);
    done_chain = chain_;
    files = target_files_;
    done = done_;
  }
  api::describe_prefilter(out, request_,
                          {envmap_name_, "/api/v1/prefilters/" + id() + "/files", done,
                           done_chain ? done_chain->source_width : 0, files.get()});
}

void PrefilterJob::ending(JobStatus, const std::optional<JobError>&) {
  envmap_.reset();
  memory_.resize(std::min(memory_.bytes(), retained_bytes()));
  memory_.set_use(MemoryUse::Held);
}

}  // namespace lp::server

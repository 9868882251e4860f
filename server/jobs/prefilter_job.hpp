#pragma once
// A prefiltered specular chain as a background job (engine/prefilter): progress in texel samples,
// checked for a cancel or a shutdown before every row, and the chain kept in memory once done, its
// bytes held in the memory budget until the job is dropped. The memory of making the chain is reserved
// when the job starts, not while it waits in the queue. Nothing is kept across restarts: a chain
// is a pure function of the map and the request, made again by a new job. So a job queued, running or
// done answers a second request of the same map content (its fingerprint) and the same parameters.
// A request with a bake target makes the target's chain (if it takes one), then the target's files,
// kept in memory beside the chain and counted in the budget with it.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "api/prefilter_request.hpp"
#include "engine/core/memory_budget.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "server/jobs/job.hpp"

namespace lp::server {

class PrefilterJob : public Job {
 public:
  PrefilterJob(std::string id, std::string envmap_name, std::shared_ptr<const EnvMap> envmap,
               std::string envmap_fingerprint, api::PrefilterRequest request, MemoryBudget budget);

  // What making the chain of `request` from `map` reserves while it runs.
  static int64_t working_bytes(const EnvMap& map, const api::PrefilterRequest& request);

  const api::PrefilterRequest& request() const { return request_; }
  // Whether this job makes, or made, the chain `request` asks of a map of `envmap_fingerprint`: the same
  // map content and every parameter the same, and the job queued, running (no cancel asked) or done.
  bool answers(const std::string& envmap_fingerprint, const api::PrefilterRequest& request) const;
  std::shared_ptr<const PrefilteredChain> chain() const;  // null until done
  // The target's files: null until done, and without a target.
  std::shared_ptr<const std::vector<api::BakeFile>> target_files() const;
  int64_t retained_bytes() const override;

 protected:
  bool run() override;
  void describe(nlohmann::json& out) const override;
  void ending(JobStatus status, const std::optional<JobError>& error) override;

 private:
  const std::string envmap_name_;
  const std::string envmap_fingerprint_;
  const api::PrefilterRequest request_;
  // Reserves the working bytes at the start; while work in flight holds them, waits for it. Empty if a
  // cancel or a shutdown came first.
  MemoryReservation reserve_working_memory() const;
  // The target's files of the finished chain (null without a target), their bytes added to memory_.
  std::shared_ptr<const std::vector<api::BakeFile>> write_target_files(const PrefilteredChain* chain);

  std::shared_ptr<const EnvMap> envmap_;  // released when the job ends
  const MemoryBudget budget_;
  MemoryReservation memory_;  // the working bytes while running; the chain's once done

  mutable std::mutex mutex_;
  std::shared_ptr<const PrefilteredChain> chain_;
  std::shared_ptr<const std::vector<api::BakeFile>> target_files_;
  bool done_ = false;
};

}  // namespace lp::server

#pragma once
// Everything the handlers share: the options and the registries.
#include <algorithm>
#include <atomic>
#include <memory>

#include "engine/core/memory_budget.hpp"
#include "engine/denoise/denoiser.hpp"
#include "server/assets/asset_registry.hpp"
#include "server/assets/model_cache.hpp"
#include "server/jobs/job_manager.hpp"
#include "server/maps/envmap_registry.hpp"
#include "server/observability/http_metrics.hpp"
#include "server/options.hpp"
#include "server/renders/render_counters.hpp"
#include "server/scale_out/mesh_bundles.hpp"
#include "server/scale_out/scale_out_counters.hpp"
#include "server/storage/state_store.hpp"

namespace lp::server {

inline JobManagerConfig render_job_config(const Options& o) {
  JobManagerConfig config = o.jobs;
  config.arena_concurrency = o.threads;
  config.max_per_client = 0;  // renders are bounded by the queue alone
  return config;
}

// Prefilters run one at a time (each takes every core its arena has), queued and kept as renders are,
// and --max-prefilters-per-client of one client at most.
inline JobManagerConfig prefilter_job_config(const Options& o) {
  JobManagerConfig config = render_job_config(o);
  config.max_running = 1;
  config.max_per_client = o.jobs.max_per_client;
  return config;
}

// Turntables run one at a time (each renders its frames on every core its arena has), queued and kept
// as renders are.
inline JobManagerConfig turntable_job_config(const Options& o) {
  JobManagerConfig config = render_job_config(o);
  config.max_running = 1;
  return config;
}

// The render arenas a server may have working at once: a render job's, a prefilter's, a turntable's, a
// Redis worker's.
inline int job_arenas(const Options& o) {
  const bool worker = o.scale_out.redis && o.scale_out.role != ServerRole::Api;
  return render_job_config(o).max_running + prefilter_job_config(o).max_running +
         turntable_job_config(o).max_running + (worker ? 1 : 0);
}

// Decodes in flight together take at most the pixels of two maps of --max-pixels (and the budget).
inline int64_t decoding_budget_bytes(const Options& o) {
  return std::min(o.max_memory_mb << 20, 2 * EnvMap::image_bytes(o.limits.max_pixels, 1));
}

struct App {
  Options options;
  MemoryBudget memory;    // --max-memory-mb: maps, their caches, images in flight, render results
  MemoryBudget decoding;  // the part of it decodes in flight may take together (see decoding_budget_bytes)
  EnvMapRegistry envmaps;
  AssetRegistry assets;        // model files uploaded for scenes (assets/stored_assets.hpp)
  ModelCache models;           // the models of scenes' mesh objects, loaded when a request names them
  MeshBundles bundles;         // the models' files, for the workers of split renders (--redis)
  denoise::Denoiser denoiser;  // of renders and turntables with `denoise` (--denoise-weights)
  ScaleOutCounters scale_out_counters;  // split renders' work items, for /metrics
  std::unique_ptr<StateStore> state;    // null: nothing is kept across restarts
  std::atomic<int> event_streams{0};    // render event streams open now
  std::atomic<bool> ready{false};       // the maps to load at start and the state directory are loaded
  HttpMetrics http_metrics;             // requests answered (GET /metrics)
  RenderCounters render_counters;       // what renders traced (GET /metrics)
  JobManager prefilters;                // prefiltered specular chains (routes/prefilter.cpp)
  JobManager turntables;                // frames orbiting a model (routes/turntables.cpp)
  JobManager renders;  // declared last: destroyed first, cancelling and joining the render jobs

  explicit App(Options opts)
      : options(std::move(opts)),
        memory(options.max_memory_mb << 20),
        decoding(decoding_budget_bytes(options)),
        envmaps(options.max_envmaps),
        assets(options.assets.max_assets),
        models(memory),
        denoiser(options.denoise_weights.value_or(denoise::default_weights_dir())),
        prefilters(prefilter_job_config(options)),
        turntables(turntable_job_config(options)),
        renders(render_job_config(options)) {}
};

}  // namespace lp::server

#pragma once
// Command-line options of lightprobe-server.
#include <spdlog/common.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/parameters.hpp"

namespace lp::server {

// Half the memory of the machine (or of its cgroup limit).
int64_t default_max_memory_mb();

// Numeric defaults, ranges and help come from api/parameters.hpp.
struct Options {
  std::string host = "127.0.0.1";
  std::vector<std::string> allowed_hosts;  // --allowed-host: Host names answered besides loopback and --host
  std::vector<std::string> cors_origins;   // --cors-origin: other origins that may call the API ("*": any)
  int port = int(api::kPort.fallback);     // 0 = any free port (printed on start)
  std::optional<std::filesystem::path> data_dir;
  std::vector<std::pair<std::string, std::string>> loads;  // --load NAME=PATH
  std::filesystem::path web_dir;                           // the dashboard, served at "/" (empty: none)
  int threads = int(api::kThreads.fallback);               // 0 = all cores
  int64_t max_upload_mb = api::kMaxUploadMb.fallback;
  int64_t max_envmaps = api::kMaxEnvmaps.fallback;
  int64_t max_assets = api::kMaxAssets.fallback;
  int64_t max_asset_mb = api::kMaxAssetMb.fallback;  // an upload, and its unpacked files together
  int64_t max_asset_files = api::kMaxAssetFiles.fallback;
  api::RequestLimits
      limits;  // --max-pixels, --max-samples, --max-lights, --max-render-*, --max-mesh-triangles
  // Budget for maps, their derived tables, images in flight and render results (see memory_budget.hpp).
  int64_t max_memory_mb = default_max_memory_mb();
  spdlog::level::level_enum log_level = spdlog::level::info;   // least severe messages written
  int64_t access_log_sample = api::kAccessLogSample.fallback;  // log 1 request in N (0: none; 5xx always)
  bool list_routes = false;  // print "METHOD PATH" per registered route and exit
  // Render jobs (POST /api/v1/renders).
  int max_running_jobs = int(api::kMaxRunningJobs.fallback);
  int max_queued_jobs = int(api::kMaxQueuedJobs.fallback);
  int max_finished_jobs = int(api::kMaxFinishedJobs.fallback);
  int64_t max_finished_mb = api::kMaxFinishedMb.fallback;       // images kept by finished jobs
  int max_event_streams = int(api::kMaxEventStreams.fallback);  // concurrent GET .../events streams
  // Connections (server/http_transport.hpp).
  int max_connections = int(api::kMaxConnections.fallback);
  int max_connections_per_client = int(api::kMaxConnectionsPerClient.fallback);
  int header_timeout_s = int(api::kHeaderTimeoutS.fallback);
  int io_timeout_s = int(api::kIoTimeoutS.fallback);
  int keep_alive_timeout_s = int(api::kKeepAliveTimeoutS.fallback);
  // Lifecycle: what survives a restart, and how a stop ends the work in flight.
  std::filesystem::path state_dir = "lightprobe-state";  // relative to the working directory
  bool resume_interrupted = false;                       // resume interrupted renders at start
  int shutdown_grace_s = int(api::kShutdownGraceS.fallback);
};

// Parses argv over `defaults`. Returns nullopt after printing --help or --version (exit 0); throws
// std::invalid_argument with a message for a bad flag (exit 2).
std::optional<Options> parse_options(int argc, char** argv, Options defaults = {});

}  // namespace lp::server

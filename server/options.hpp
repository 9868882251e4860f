#pragma once
// Command-line options of lightprobe-server.
#include <spdlog/common.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/parameters.hpp"
#include "server/jobs/thread_priority.hpp"
#include "server/observability/log_format.hpp"
#include "server/scale_out/redis_url.hpp"
#include "server/scale_out/server_role.hpp"

namespace lp::server {

// Half the memory of the machine (or of its cgroup limit).
int64_t default_max_memory_mb();

// Numeric defaults, ranges and help come from api/parameters.hpp.
struct Options {
  std::string host = "127.0.0.1";
  std::vector<std::string> allowed_hosts;  // --allowed-host: Host names answered besides loopback and --host
  std::vector<std::string> cors_origins;   // --cors-origin: other origins that may call the API ("*": any)
  std::optional<std::filesystem::path> auth_token_file;  // --auth-token-file
  std::string auth_token;               // read from it by load_auth_token(); empty: the API needs no token
  int port = int(api::kPort.fallback);  // 0 = any free port (printed on start)
  std::optional<std::filesystem::path> data_dir;
  std::vector<std::pair<std::string, std::string>> loads;  // --load NAME=PATH
  std::filesystem::path web_dir;                           // the dashboard, served at "/" (empty: none)
  int threads = int(api::kThreads.fallback);               // 0 = all cores
  int64_t max_upload_mb = api::kMaxUploadMb.fallback;
  int64_t max_envmaps = api::kMaxEnvmaps.fallback;
  int64_t max_assets = api::kMaxAssets.fallback;
  int64_t max_asset_mb = api::kMaxAssetMb.fallback;  // an upload, and its unpacked files together
  int64_t max_asset_files = api::kMaxAssetFiles.fallback;
  // --max-pixels, --max-samples, --max-lights, --max-render-*, --max-mesh-triangles, --max-*texture-pixels
  api::RequestLimits limits;
  // Budget for maps, their derived tables, images in flight and render results (see memory_budget.hpp).
  int64_t max_memory_mb = default_max_memory_mb();
  spdlog::level::level_enum log_level = spdlog::level::info;  // least severe messages written
  LogFormat log_format = LogFormat::Text;
  int64_t access_log_sample = api::kAccessLogSample.fallback;  // log 1 request in N (0: none; 5xx always)
  bool list_routes = false;      // print "METHOD PATH" per registered route and exit
  std::string health_check_url;  // --health-check: probe this URL and exit (server/health_check.hpp)
  // Render jobs (POST /api/v1/renders).
  int max_running_jobs = int(api::kMaxRunningJobs.fallback);
  int max_queued_jobs = int(api::kMaxQueuedJobs.fallback);
  int max_finished_jobs = int(api::kMaxFinishedJobs.fallback);
  int64_t max_finished_mb = api::kMaxFinishedMb.fallback;       // images kept by finished jobs
  RenderPriority render_priority = RenderPriority::Low;         // of the threads that render
  int max_event_streams = int(api::kMaxEventStreams.fallback);  // concurrent GET .../events streams
  // Connections (server/http/http_transport.hpp).
  int max_connections = int(api::kMaxConnections.fallback);
  int max_connections_per_client = int(api::kMaxConnectionsPerClient.fallback);
  int header_timeout_s = int(api::kHeaderTimeoutS.fallback);
  int io_timeout_s = int(api::kIoTimeoutS.fallback);
  int keep_alive_timeout_s = int(api::kKeepAliveTimeoutS.fallback);
  // Lifecycle: what survives a restart, and how a stop ends the work in flight.
  std::filesystem::path state_dir = "lightprobe-state";  // relative to the working directory
  bool resume_interrupted = false;                       // resume interrupted renders at start
  int shutdown_grace_s = int(api::kShutdownGraceS.fallback);
  // Renders split over machines through Redis (server/scale_out/scale_out.hpp).
  std::optional<RedisAddress> redis;  // --redis; none: renders run in this process
  ServerRole role = ServerRole::Both;
  std::string advertise_url;  // where workers fetch maps from this server; empty: http://--host:port
  int redis_item_spp = int(api::kRedisItemSpp.fallback);
  int redis_claim_timeout_s = int(api::kRedisClaimTimeoutS.fallback);
};

// Reads the token of --auth-token-file, if set, into auth_token; throws std::invalid_argument if it cannot.
void load_auth_token(Options& options);

// The value of an environment variable, nullopt when it is unset.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;
Environment process_environment();

// The variable that sets a flag: "max-pixels" -> "LIGHTPROBE_MAX_PIXELS".
std::string environment_variable(std::string_view flag);

// Parses argv over `defaults`, each flag not on the command line taken from its variable in `environment`
// (an empty variable counts as unset). Returns nullopt after printing --help or --version (exit 0);
// throws std::invalid_argument with a message for a bad flag or variable (exit 2).
std::optional<Options> parse_options(int argc, char** argv, Options defaults = {},
                                     const Environment& environment = process_environment());

}  // namespace lp::server

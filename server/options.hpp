#pragma once
// Command-line options of lightprobe-server: the process's own, and the configuration of each subsystem,
// declared with the subsystem together with the flags of its numbers and composed here. The flags, their
// variables and --help: options.cpp over flag_parser.hpp.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/parameters.hpp"
#include "server/assets/asset_limits.hpp"
#include "server/flag_parser.hpp"
#include "server/http/browser_policy_config.hpp"
#include "server/http/transport_limits.hpp"
#include "server/jobs/job_manager_config.hpp"
#include "server/maps/envmap_registry.hpp"
#include "server/observability/log_config.hpp"
#include "server/renders/event_streams.hpp"
#include "server/scale_out/scale_out_config.hpp"

namespace lp::server {

inline constexpr api::IntParameter kPort{
    "port", 8080, {0, 65535}, "port (0 picks a free port, printed on start)"};
inline constexpr api::IntParameter kMaxMemoryMb{
    "max-memory-mb",
    0,
    {1, int64_t{1} << 30},
    "MiB for maps, their sampling tables and caches, images in flight and render results; past it, caches "
    "are evicted, then requests get 503 or 507",
    "half the machine's memory, or of its cgroup limit"};
inline constexpr api::IntParameter kShutdownGraceS{
    "shutdown-grace-s", 10, {0, 3600}, "on SIGTERM/SIGINT, seconds running renders get to finish their pass"};

// Half the memory of the machine (or of its cgroup limit).
int64_t default_max_memory_mb();

struct Options {
  // The process: where it listens, what it serves and keeps, and how it stops.
  std::string host = "127.0.0.1";
  int port = int(kPort.fallback);  // 0 = any free port (printed on start)
  std::optional<std::filesystem::path> auth_token_file;
  std::string auth_token;  // read from it by load_auth_token(); empty: the API needs no token
  std::optional<std::filesystem::path> data_dir;
  std::vector<std::pair<std::string, std::string>> loads;  // --load NAME=PATH
  std::filesystem::path web_dir;                           // the dashboard, served at "/" (empty: none)
  // The denoiser's weights (engine/denoise/); absent: denoise::default_weights_dir().
  std::optional<std::filesystem::path> denoise_weights;
  int threads = int(api::kThreads.fallback);  // 0 = all cores
  // Budget for maps, their derived tables, images in flight and render results (see memory_budget.hpp).
  int64_t max_memory_mb = default_max_memory_mb();
  int64_t max_envmaps = kMaxEnvmaps.fallback;
  int max_event_streams = int(kMaxEventStreams.fallback);  // concurrent GET .../events streams
  std::filesystem::path state_dir = "lightprobe-state";    // relative to the working directory
  bool resume_interrupted = false;                         // resume interrupted renders at start
  int shutdown_grace_s = int(kShutdownGraceS.fallback);
  bool list_routes = false;      // print "METHOD PATH" per registered route and exit
  std::string health_check_url;  // --health-check: probe this URL or PATH and exit (health_check.hpp)

  // The subsystems'.
  BrowserPolicyConfig browser;  // --allowed-host, --cors-origin
  TransportLimits transport;    // --max-connections..., --max-upload-mb
  // --max-pixels, --max-samples, --max-lights, --max-render-*, --max-mesh-triangles, --max-*texture-pixels
  api::RequestLimits limits;
  AssetLimits assets;     // --max-assets, --max-asset-mb, --max-asset-files
  JobManagerConfig jobs;  // --max-*-jobs, --max-finished-mb, --render-priority, --max-prefilters-per-client
  LogConfig log;          // --log-level, --log-format, --access-log-sample
  ScaleOutConfig scale_out;  // --redis, --role, --advertise-url, --redis-*
};

// Every integer flag's declaration, in --help order.
std::vector<const api::IntParameter*> int_flag_parameters();

// Reads the token of --auth-token-file, if set, into auth_token; throws std::invalid_argument if it cannot.
void load_auth_token(Options& options);

// Parses argv over `defaults`, each flag not on the command line taken from its variable in `environment`
// (an empty variable counts as unset). Returns nullopt after printing --help or --version (exit 0);
// throws std::invalid_argument with a message for a bad flag or variable (exit 2).
std::optional<Options> parse_options(int argc, char** argv, Options defaults = {},
                                     const Environment& environment = process_environment());

}  // namespace lp::server

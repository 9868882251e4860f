#pragma once
// Command-line options of lightprobe-server.
#include <spdlog/common.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lp::server {

// Half the memory of the machine (or of its cgroup limit).
int64_t default_max_memory_mb();

struct Options {
  std::string host = "127.0.0.1";
  std::vector<std::string> allowed_hosts;  // --allowed-host: Host names answered besides loopback and --host
  std::vector<std::string> cors_origins;   // --cors-origin: other origins that may call the API ("*": any)
  int port = 8080;                         // 0 = any free port (printed on start)
  std::optional<std::filesystem::path> data_dir;
  std::vector<std::pair<std::string, std::string>> loads;  // --load NAME=PATH
  std::filesystem::path web_dir;                           // the dashboard, served at "/" (empty: none)
  int threads = 0;                                         // 0 = all cores
  int64_t max_upload_mb = 512;
  int64_t max_pixels = int64_t{8192} * 4096;
  int64_t max_samples = 10'000'000;
  int64_t max_envmaps = 64;
  int64_t max_lights = 65536;
  // Budget for maps, their derived tables, images in flight and render results (see memory_budget.hpp).
  int64_t max_memory_mb = default_max_memory_mb();
  spdlog::level::level_enum log_level = spdlog::level::info;  // least severe messages written
  int64_t access_log_sample = 1;                              // log 1 request in N (0: none; 5xx always)
  bool list_routes = false;  // print "METHOD PATH" per registered route and exit
  // Renders (POST /api/v1/renders).
  int max_render_width = 4096;
  int max_render_height = 4096;
  int max_render_spp = 65536;
  int max_render_depth = 64;
  int max_render_objects = 256;
  int64_t max_mesh_triangles = 2'000'000;
  int max_running_jobs = 2;
  int max_queued_jobs = 16;
  int max_finished_jobs = 64;
  int64_t max_finished_mb = 1024;  // images kept by finished jobs
  int max_event_streams = 8;       // concurrent GET .../events streams
  // Connections (server/http_transport.hpp).
  int max_connections = 1024;            // open at once; more are refused with 503
  int max_connections_per_client = 512;  // open at once from one client address; more are refused with 503
  int header_timeout_s = 10;             // for a request line and its headers to arrive (else 408)
  int io_timeout_s = 30;                 // longest wait of a body read or a response write
  int keep_alive_timeout_s = 5;          // idle time before a keep-alive connection is closed
  // Lifecycle: what survives a restart, and how a stop ends the work in flight.
  std::filesystem::path state_dir = "lightprobe-state";  // relative to the working directory
  bool resume_interrupted = false;                       // resume interrupted renders at start
  int shutdown_grace_s = 10;  // on SIGTERM/SIGINT, time for running renders to finish their pass
};

// Parses argv over `defaults`. Returns nullopt after printing --help or --version (exit 0); throws
// std::invalid_argument with a message for a bad flag (exit 2).
std::optional<Options> parse_options(int argc, char** argv, Options defaults = {});

}  // namespace lp::server

#include "server/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "server/log_level.hpp"
#include "server/machine_memory.hpp"

namespace lp::server {
namespace {

constexpr const char* kUsage = R"(lightprobe-server: image-based lighting over HTTP/JSON

Usage: lightprobe-server [options]

  --host ADDR            address to listen on (default 127.0.0.1)
  --port N               port (default 8080; 0 picks a free port, printed on start)
  --allowed-host NAME    a Host header name to answer besides loopback and --host (repeatable); others
                         get 403 (a defence against DNS rebinding)
  --cors-origin ORIGIN   an origin (http://host:port, or *) whose pages may call the API (repeatable);
                         without it, requests that change state from another origin get 403
  --data-dir DIR         maps, meshes and scene files loadable by relative path come only from here
  --load NAME=PATH       load a map at start (repeatable); PATH absolute or relative to the working directory
  --web-dir DIR          static dashboard served at / (default: the source tree's web/); the API keeps /api
  --threads N            worker threads for computation (default: all cores)
  --max-upload-mb N      largest request body in MiB (default 512)
  --max-pixels N         largest map in pixels (default 33554432 = 8192 x 4096)
  --max-samples N        most samples per request (default 10000000)
  --max-envmaps N        most maps held at once (default 64)
  --max-lights N         most median-cut lights per request (default 65536)
  --max-memory-mb N      MiB for maps, their sampling tables and caches, images in flight and render
                         results; past it, caches are evicted, then requests get 503 or 507
                         (default: half the machine's memory, or of its cgroup limit)
  --max-render-width N   widest render in pixels (default 4096)
  --max-render-height N  tallest render in pixels (default 4096)
  --max-render-spp N     most samples per pixel of a render (default 65536)
  --max-render-depth N   largest max_depth (path bounces) of a render (default 64)
  --max-render-objects N most objects in a render's scene (default 256)
  --max-mesh-triangles N most triangles in one mesh of a render (default 2000000)
  --max-running-jobs N   renders running at once, each in its own thread arena (default 2)
  --max-queued-jobs N    renders waiting to run; a full queue answers 503 (default 16)
  --max-finished-jobs N  finished renders kept with their images, oldest dropped (default 64)
  --max-finished-mb N    MiB of images kept by finished renders, oldest dropped (default 1024)
  --max-event-streams N  concurrent render event streams (default 8)
  --max-connections N    open connections at once; more are refused with 503 (default 1024)
  --max-connections-per-client N
                         open connections from one client address; more are refused with 503 (default 512)
  --header-timeout-s N   seconds for a request line and its headers to arrive; then 408 (default 10)
  --io-timeout-s N       seconds a body read or a response write may wait; then the connection closes (default 30)
  --keep-alive-timeout-s N
                         seconds an idle keep-alive connection stays open (default 5)
  --state-dir DIR        uploaded maps and render jobs kept across restarts (default ./lightprobe-state)
  --resume-interrupted   at start, resume the renders a crash or a stop interrupted
  --shutdown-grace-s N   on SIGTERM/SIGINT, seconds running renders get to finish their pass (default 10)
  --log-level NAME       least severe messages written: {levels} (default info)
  --access-log-sample N  access log: one line per N requests at info level, 0 for none; a 5xx answer
                         is always logged, at error level (default 1: every request)
  --list-routes          print every registered route (METHOD PATH) and exit
  --version              print the version and exit
  --help                 print this help and exit
)";

int64_t parse_count(const std::string& flag, const std::string& value, int64_t min, int64_t max) {
  try {
    size_t used = 0;
    const long long v = std::stoll(value, &used);
    if (used == value.size() && v >= min && v <= max) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(
      fmt::format("{} takes an integer in [{}, {}], got '{}'", flag, min, max, value));
}

}  // namespace

int64_t default_max_memory_mb() {
  return std::max<int64_t>(1, machine_memory_bytes() / 2 >> 20);
}

std::optional<Options> parse_options(int argc, char** argv, Options defaults) {
  Options o = std::move(defaults);
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h") {
      std::cout << fmt::format(fmt::runtime(kUsage), fmt::arg("levels", log_level_names()));
      return std::nullopt;
    } else if (flag == "--version") {
      std::cout << "lightprobe-server " << LIGHTPROBE_VERSION << "\n";
      return std::nullopt;
    } else if (flag == "--log-level") {
      o.log_level = parse_log_level(value());
    } else if (flag == "--access-log-sample") {
      o.access_log_sample = parse_count(flag, value(), 0, int64_t{1} << 40);
    } else if (flag == "--list-routes") {
      o.list_routes = true;
    } else if (flag == "--host") {
      o.host = value();
    } else if (flag == "--allowed-host") {
      o.allowed_hosts.push_back(value());
    } else if (flag == "--cors-origin") {
      o.cors_origins.push_back(value());
    } else if (flag == "--port") {
      o.port = int(parse_count(flag, value(), 0, 65535));
    } else if (flag == "--data-dir") {
      o.data_dir = value();
    } else if (flag == "--load") {
      const std::string v = value();
      const auto eq = v.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == v.size())
        throw std::invalid_argument("--load takes NAME=PATH, got '" + v + "'");
      o.loads.emplace_back(v.substr(0, eq), v.substr(eq + 1));
    } else if (flag == "--web-dir") {
      o.web_dir = value();
    } else if (flag == "--threads") {
      o.threads = int(parse_count(flag, value(), 1, 1024));
    } else if (flag == "--max-upload-mb") {
      o.max_upload_mb = parse_count(flag, value(), 1, 1 << 20);
    } else if (flag == "--max-pixels") {
      o.max_pixels = parse_count(flag, value(), 1, int64_t{1} << 34);
    } else if (flag == "--max-samples") {
      o.max_samples = parse_count(flag, value(), 1, int64_t{1} << 32);
    } else if (flag == "--max-envmaps") {
      o.max_envmaps = parse_count(flag, value(), 1, 100000);
    } else if (flag == "--max-memory-mb") {
      o.max_memory_mb = parse_count(flag, value(), 1, int64_t{1} << 30);
    } else if (flag == "--max-lights") {
      o.max_lights = parse_count(flag, value(), 1, int64_t{1} << 24);
    } else if (flag == "--max-render-width") {
      o.max_render_width = int(parse_count(flag, value(), 1, 65536));
    } else if (flag == "--max-render-height") {
      o.max_render_height = int(parse_count(flag, value(), 1, 65536));
    } else if (flag == "--max-render-spp") {
      o.max_render_spp = int(parse_count(flag, value(), 1, 1 << 24));
    } else if (flag == "--max-render-depth") {
      o.max_render_depth = int(parse_count(flag, value(), 0, 1024));
    } else if (flag == "--max-render-objects") {
      o.max_render_objects = int(parse_count(flag, value(), 0, 1 << 20));
    } else if (flag == "--max-mesh-triangles") {
      o.max_mesh_triangles = parse_count(flag, value(), 1, int64_t{1} << 32);
    } else if (flag == "--max-running-jobs") {
      o.max_running_jobs = int(parse_count(flag, value(), 1, 256));
    } else if (flag == "--max-queued-jobs") {
      o.max_queued_jobs = int(parse_count(flag, value(), 0, 1 << 20));
    } else if (flag == "--max-finished-jobs") {
      o.max_finished_jobs = int(parse_count(flag, value(), 1, 1 << 20));
    } else if (flag == "--max-finished-mb") {
      o.max_finished_mb = parse_count(flag, value(), 1, 1 << 24);
    } else if (flag == "--max-event-streams") {
      o.max_event_streams = int(parse_count(flag, value(), 0, 4096));
    } else if (flag == "--max-connections") {
      o.max_connections = int(parse_count(flag, value(), 1, 1 << 20));
    } else if (flag == "--max-connections-per-client") {
      o.max_connections_per_client = int(parse_count(flag, value(), 1, 1 << 20));
    } else if (flag == "--header-timeout-s") {
      o.header_timeout_s = int(parse_count(flag, value(), 1, 3600));
    } else if (flag == "--io-timeout-s") {
      o.io_timeout_s = int(parse_count(flag, value(), 1, 3600));
    } else if (flag == "--keep-alive-timeout-s") {
      o.keep_alive_timeout_s = int(parse_count(flag, value(), 1, 3600));
    } else if (flag == "--state-dir") {
      o.state_dir = value();
      if (o.state_dir.empty()) throw std::invalid_argument("--state-dir needs a directory");
    } else if (flag == "--resume-interrupted") {
      o.resume_interrupted = true;
    } else if (flag == "--shutdown-grace-s") {
      o.shutdown_grace_s = int(parse_count(flag, value(), 0, 3600));
    } else {
      throw std::invalid_argument("unknown option '" + flag + "' (see --help)");
    }
  }
  return o;
}

}  // namespace lp::server

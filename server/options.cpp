#include "server/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <type_traits>

#include "server/log_level.hpp"
#include "server/machine_memory.hpp"

namespace lp::server {
namespace {

constexpr const char* kUsageHead = R"(lightprobe-server: image-based lighting over HTTP/JSON

Usage: lightprobe-server [options]

  --host ADDR            address to listen on (default 127.0.0.1)
  --allowed-host NAME    a Host header name to answer besides loopback and --host (repeatable); others
                         get 403 (a defence against DNS rebinding)
  --cors-origin ORIGIN   an origin (http://host:port, or *) whose pages may call the API (repeatable);
                         without it, requests that change state from another origin get 403
  --data-dir DIR         maps, meshes and scene files loadable by relative path come only from here
                         (mesh paths assets/NAME name uploaded model assets instead)
  --load NAME=PATH       load a map at start (repeatable); PATH absolute or relative to the working directory
  --web-dir DIR          static dashboard served at / (default: the source tree's web/); the API keeps /api
  --state-dir DIR        uploaded maps, model assets and render jobs kept across restarts
                         (default ./lightprobe-state)
  --resume-interrupted   at start, resume the renders a crash or a stop interrupted
  --log-level NAME       least severe messages written: {levels} (default info)
  --list-routes          print every registered route (METHOD PATH) and exit
  --version              print the version and exit
  --help                 print this help and exit
)";

// An integer flag: its declaration and where its value goes.
struct IntFlag {
  const api::IntParameter* parameter;
  void (*set)(Options&, int64_t);
};

template <auto Member>
IntFlag option(const api::IntParameter& p) {
  return {&p, [](Options& o, int64_t v) {
            o.*Member = static_cast<std::remove_reference_t<decltype(o.*Member)>>(v);
          }};
}

template <auto Member>
IntFlag request_limit(const api::IntParameter& p) {
  return {&p, [](Options& o, int64_t v) { o.limits.*Member = v; }};
}

const std::vector<IntFlag>& int_flags() {
  static const std::vector<IntFlag> flags = {
      option<&Options::port>(api::kPort),
      option<&Options::threads>(api::kThreads),
      option<&Options::max_upload_mb>(api::kMaxUploadMb),
      request_limit<&api::RequestLimits::max_pixels>(api::kMaxPixels),
      request_limit<&api::RequestLimits::max_samples>(api::kMaxSamples),
      option<&Options::max_envmaps>(api::kMaxEnvmaps),
      request_limit<&api::RequestLimits::max_lights>(api::kMaxLights),
      option<&Options::max_assets>(api::kMaxAssets),
      option<&Options::max_asset_mb>(api::kMaxAssetMb),
      option<&Options::max_asset_files>(api::kMaxAssetFiles),
      option<&Options::max_memory_mb>(api::kMaxMemoryMb),
      request_limit<&api::RequestLimits::max_render_width>(api::kMaxRenderWidth),
      request_limit<&api::RequestLimits::max_render_height>(api::kMaxRenderHeight),
      request_limit<&api::RequestLimits::max_render_spp>(api::kMaxRenderSpp),
      request_limit<&api::RequestLimits::max_render_depth>(api::kMaxRenderDepth),
      request_limit<&api::RequestLimits::max_render_objects>(api::kMaxRenderObjects),
      request_limit<&api::RequestLimits::max_mesh_triangles>(api::kMaxMeshTriangles),
      option<&Options::max_running_jobs>(api::kMaxRunningJobs),
      option<&Options::max_queued_jobs>(api::kMaxQueuedJobs),
      option<&Options::max_finished_jobs>(api::kMaxFinishedJobs),
      option<&Options::max_finished_mb>(api::kMaxFinishedMb),
      option<&Options::max_event_streams>(api::kMaxEventStreams),
      option<&Options::max_connections>(api::kMaxConnections),
      option<&Options::max_connections_per_client>(api::kMaxConnectionsPerClient),
      option<&Options::header_timeout_s>(api::kHeaderTimeoutS),
      option<&Options::io_timeout_s>(api::kIoTimeoutS),
      option<&Options::keep_alive_timeout_s>(api::kKeepAliveTimeoutS),
      option<&Options::shutdown_grace_s>(api::kShutdownGraceS),
      option<&Options::access_log_sample>(api::kAccessLogSample),
  };
  return flags;
}

std::string int_flag_help(const api::IntParameter& p) {
  const std::string name = fmt::format("--{} N", p.flag);
  const std::string fallback = p.default_text ? p.default_text : std::to_string(p.fallback);
  const std::string text = fmt::format("{} (default {})", p.help, fallback);
  if (name.size() > 21) return fmt::format("  {}\n  {:21}  {}\n", name, "", text);
  return fmt::format("  {:21}  {}\n", name, text);
}

// The flag of every declared integer parameter (api::int_parameters(), in that order).
const IntFlag& int_flag(const api::IntParameter& p) {
  for (const IntFlag& f : int_flags())
    if (f.parameter == &p) return f;
  throw std::logic_error(fmt::format("--{} is declared but sets no option", p.flag));
}

std::string usage() {
  std::string out = fmt::format(fmt::runtime(kUsageHead), fmt::arg("levels", log_level_names()));
  out += "\nNumbers:\n";
  for (const api::IntParameter* p : api::int_parameters()) out += int_flag_help(*p);
  return out;
}

int64_t parse_count(const std::string& flag, const std::string& value, Range<int64_t> range) {
  try {
    size_t used = 0;
    const long long v = std::stoll(value, &used);
    if (used == value.size() && range.contains(v)) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(
      fmt::format("{} takes an integer in [{}, {}], got '{}'", flag, range.min, range.max, value));
}

// Sets the integer flag named `flag` and returns true, or returns false if no integer flag has that name.
bool set_int_flag(Options& o, const std::string& flag, const std::function<std::string()>& value) {
  for (const api::IntParameter* p : api::int_parameters())
    if (flag == fmt::format("--{}", p->flag)) {
      int_flag(*p).set(o, parse_count(flag, value(), p->range));
      return true;
    }
  return false;
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
      std::cout << usage();
      return std::nullopt;
    } else if (flag == "--version") {
      std::cout << "lightprobe-server " << LIGHTPROBE_VERSION << "\n";
      return std::nullopt;
    } else if (flag == "--log-level") {
      o.log_level = parse_log_level(value());
    } else if (set_int_flag(o, flag, value)) {
    } else if (flag == "--list-routes") {
      o.list_routes = true;
    } else if (flag == "--host") {
      o.host = value();
    } else if (flag == "--allowed-host") {
      o.allowed_hosts.push_back(value());
    } else if (flag == "--cors-origin") {
      o.cors_origins.push_back(value());
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
    } else if (flag == "--state-dir") {
      o.state_dir = value();
      if (o.state_dir.empty()) throw std::invalid_argument("--state-dir needs a directory");
    } else if (flag == "--resume-interrupted") {
      o.resume_interrupted = true;
    } else {
      throw std::invalid_argument("unknown option '" + flag + "' (see --help)");
    }
  }
  return o;
}

}  // namespace lp::server

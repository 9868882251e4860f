#include "server/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <type_traits>

#include "server/health_check.hpp"
#include "server/http/bearer_auth.hpp"
#include "server/observability/log_level.hpp"
#include "server/observability/machine_memory.hpp"

namespace lp::server {
namespace {

constexpr const char* kUsageHead = R"(lightprobe-server: image-based lighting over HTTP/JSON

Usage: lightprobe-server [options]

)";

constexpr const char* kActions =
    R"(  --list-routes          print every registered route (METHOD PATH) and exit
  --health-check URL     GET the URL (http://HOST[:PORT]/PATH) with a {health_timeout} s timeout and exit:
                         0 if it answers 200, 1 otherwise (a container's HEALTHCHECK)
  --version              print the version and exit
  --help                 print this help and exit
)";

constexpr const char* kEnvironmentHead = R"(
Environment: every flag but --list-routes, --health-check, --version and --help can be given as a variable
instead: LIGHTPROBE_ and its name in upper case, - written _ (--max-pixels: LIGHTPROBE_MAX_PIXELS). A flag on the
command line wins over its variable; an empty variable counts as unset; a repeatable flag's variable takes a
comma-separated list, a switch's 1, true, yes or 0, false, no. The variables:
)";

constexpr size_t kHelpWidth = 110;
constexpr size_t kNameColumn = 21;

// A flag that is not an integer of api/parameters: a value of its own kind, or a switch.
struct TextFlag {
  const char* name;   // without the dashes
  const char* value;  // what it takes, as --help shows it ("ADDR"); nullptr for a switch
  std::string help;   // a line break starts a line under the first
  bool repeatable;    // every use adds a value
  void (*set)(Options&, const std::string&);  // a switch's value is "" (it is only set when on)
};

void add_load(Options& o, const std::string& v) {
  const auto eq = v.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == v.size())
    throw std::invalid_argument("--load takes NAME=PATH, got '" + v + "'");
  o.loads.emplace_back(v.substr(0, eq), v.substr(eq + 1));
}

void set_state_dir(Options& o, const std::string& v) {
  if (v.empty()) throw std::invalid_argument("--state-dir needs a directory");
  o.state_dir = v;
}

// The value of an enum flag, by the names of its enum_entries.
template <class E>
E enum_value(const char* flag, const std::string& v) {
  const auto value = parse_enum<E>(v);
  if (!value)
    throw std::invalid_argument(
        fmt::format("--{} takes one of {}, got '{}'", flag, enum_names_joined<E>("|"), v));
  return *value;
}

void set_log_format(Options& o, const std::string& v) {
  o.log_format = enum_value<LogFormat>("log-format", v);
}

void set_render_priority(Options& o, const std::string& v) {
  o.render_priority = enum_value<RenderPriority>("render-priority", v);
}

void set_role(Options& o, const std::string& v) {
  o.role = enum_value<ServerRole>("role", v);
}

// A server of one role only splits jobs with others, through Redis.
void check_role(const Options& o) {
  if (o.role != ServerRole::Both && !o.redis)
    throw std::invalid_argument(fmt::format("--role {} needs --redis redis://HOST:PORT", enum_name(o.role)));
}

const std::vector<TextFlag>& text_flags() {
  static const std::vector<TextFlag> flags = {
      {"host", "ADDR", "address to listen on (default 127.0.0.1)", false,
       [](Options& o, const std::string& v) { o.host = v; }},
      {"allowed-host", "NAME",
       "a Host header name to answer besides loopback and --host (repeatable); others\nget 403 (a "
       "defence against DNS rebinding)",
       true, [](Options& o, const std::string& v) { o.allowed_hosts.push_back(v); }},
      {"cors-origin", "ORIGIN",
       "an origin (http://host:port, or *) whose pages may call the API (repeatable);\nwithout it, "
       "requests that change state from another origin get 403",
       true, [](Options& o, const std::string& v) { o.cors_origins.push_back(v); }},
      {"auth-token-file", "FILE",
       "when given, every API route but /api/v1/health and /api/v1/ready, and /metrics,\nneed "
       "Authorization: Bearer TOKEN, the token FILE holds (others get 401)",
       false, [](Options& o, const std::string& v) { o.auth_token_file = v; }},
      {"data-dir", "DIR",
       "maps and models loadable by relative path come only from here: a mesh path\nnames a .gltf, .glb "
       "or .obj, whose .bin, .mtl and texture files lie beside it\n(mesh paths assets/NAME name models "
       "uploaded with POST /api/v1/assets instead)",
       false, [](Options& o, const std::string& v) { o.data_dir = v; }},
      {"load", "NAME=PATH",
       "load a map at start (repeatable); PATH absolute or relative to the working directory", true,
       add_load},
      {"web-dir", "DIR", "static dashboard served at / (default: the source tree's web/); the API keeps /api",
       false, [](Options& o, const std::string& v) { o.web_dir = v; }},
      {"state-dir", "DIR",
       "uploaded maps, model assets and render jobs kept across restarts\n(default ./lightprobe-state)",
       false, set_state_dir},
      {"render-priority", "NAME",
       enum_names_joined<RenderPriority>("|") +
           ": how render threads yield to requests and other programs: nice\n+" +
           std::to_string(kLowRenderNiceStep) + " from the server's own" +
           ", or only cores nothing else wants (renders stall while something else\nkeeps the cores "
           "busy), or no lower than the rest (default low)",
       false, set_render_priority},
      {"resume-interrupted", nullptr, "at start, resume the renders a crash or a stop interrupted", false,
       [](Options& o, const std::string&) { o.resume_interrupted = true; }},
      {"redis", "URL",
       "redis://HOST[:PORT]: split renders into work items of sample ranges on Redis\nStreams, rendered by "
       "every server of that Redis (see --role)",
       false, [](Options& o, const std::string& v) { o.redis = parse_redis_url(v); }},
      {"role", "NAME",
       enum_names_joined<ServerRole>("|") +
           " with --redis: accept renders and merge their items, render items, or\nboth (default both)",
       false, set_role},
      {"advertise-url", "URL",
       "with --redis, where workers fetch this server's maps (default\nhttp://HOST:PORT of --host and the "
       "port)",
       false, [](Options& o, const std::string& v) { o.advertise_url = v; }},
      {"log-level", "NAME", "least severe messages written: " + log_level_names() + " (default info)", false,
       [](Options& o, const std::string& v) { o.log_level = parse_log_level(v); }},
      {"log-format", "NAME",
       enum_names_joined<LogFormat>("|") +
           ": lines for people, or one JSON object a line (time, level, message; access\nlines also "
           "request_id, method, path, route, status, duration_ms, client)\n(default text)",
       false, set_log_format},
  };
  return flags;
}

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
      request_limit<&api::RequestLimits::max_texture_pixels>(api::kMaxTexturePixels),
      request_limit<&api::RequestLimits::max_model_texture_pixels>(api::kMaxModelTexturePixels),
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
      option<&Options::redis_item_spp>(api::kRedisItemSpp),
      option<&Options::redis_claim_timeout_s>(api::kRedisClaimTimeoutS),
  };
  return flags;
}

// The flag of every declared integer parameter (api::int_parameters(), in that order).
const IntFlag& int_flag(const api::IntParameter& p) {
  for (const IntFlag& f : int_flags())
    if (f.parameter == &p) return f;
  throw std::logic_error(fmt::format("--{} is declared but sets no option", p.flag));
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

// Any flag that sets an option, text or integer, as the parser, the environment and --help see it.
struct Flag {
  std::string name;   // without the dashes
  std::string usage;  // "--name VALUE"
  std::string help;
  bool takes_value;
  bool repeatable;
  std::function<void(Options&, const std::string&)> set;
};

const std::vector<Flag>& flags() {
  static const std::vector<Flag> all = [] {
    std::vector<Flag> out;
    for (const TextFlag& f : text_flags())
      out.push_back({f.name, f.value ? fmt::format("--{} {}", f.name, f.value) : fmt::format("--{}", f.name),
                     f.help, f.value != nullptr, f.repeatable, f.set});
    for (const api::IntParameter* p : api::int_parameters()) {
      const std::string fallback = p->default_text ? p->default_text : std::to_string(p->fallback);
      const IntFlag& f = int_flag(*p);
      out.push_back({p->flag, fmt::format("--{} N", p->flag),
                     fmt::format("{} (default {})", p->help, fallback), true, false,
                     [&f, p](Options& o, const std::string& v) {
                       f.set(o, parse_count(fmt::format("--{}", p->flag), v, p->range));
                     }});
    }
    return out;
  }();
  return all;
}

// "  --name VALUE           first line of help" and the help's further lines under its first.
std::string help_entry(const std::string& usage, const std::string& help) {
  const std::string indent(2 + kNameColumn + 2, ' ');
  std::string out;
  size_t start = 0;
  for (size_t end = 0; end != std::string::npos; start = end + 1) {
    end = help.find('\n', start);
    const std::string line = help.substr(start, end == std::string::npos ? end : end - start);
    if (start > 0)
      out += indent + line + "\n";
    else if (usage.size() > kNameColumn)
      out += fmt::format("  {}\n{}{}\n", usage, indent, line);
    else
      out += fmt::format("  {:{}}  {}\n", usage, kNameColumn, line);
  }
  return out;
}

// The variables, as many on a line as fit in the help's width.
std::string environment_list() {
  std::string out;
  size_t column = 0;
  for (const Flag& f : flags()) {
    const std::string name = environment_variable(f.name);
    if (column > 0 && column + 1 + name.size() > kHelpWidth) {
      out += '\n';
      column = 0;
    }
    out += column == 0 ? "  " : " ";
    out += name;
    column += (column == 0 ? 2 : 1) + name.size();
  }
  return out + '\n';
}

// The text flags, the actions, then the numbers (flags() lists the text flags first).
std::string usage() {
  std::string out = kUsageHead;
  for (size_t i = 0; i < flags().size(); ++i) {
    if (i == text_flags().size())
      out += fmt::format(fmt::runtime(kActions), fmt::arg("health_timeout", kHealthCheckTimeout.count())) +
             "\nNumbers:\n";
    out += help_entry(flags()[i].usage, flags()[i].help);
  }
  return out + kEnvironmentHead + environment_list();
}

const Flag* find_flag(const std::string& arg) {
  for (const Flag& f : flags())
    if (arg == "--" + f.name) return &f;
  return nullptr;
}

// A switch's variable: on or off.
bool switch_value(const std::string& flag, const std::string& value) {
  for (const char* on : {"1", "true", "yes"})
    if (value == on) return true;
  for (const char* off : {"0", "false", "no"})
    if (value == off) return false;
  throw std::invalid_argument(
      fmt::format("--{} is a switch: 1, true, yes or 0, false, no, got '{}'", flag, value));
}

// "a, b,c" -> {"a", "b", "c"}: a repeatable flag's variable.
std::vector<std::string> list_items(const std::string& value) {
  std::vector<std::string> items;
  size_t start = 0;
  for (size_t end = 0; end != std::string::npos; start = end + 1) {
    end = value.find(',', start);
    std::string item = value.substr(start, end == std::string::npos ? end : end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) items.push_back(std::move(item));
  }
  return items;
}

void set_from_environment(Options& o, const Flag& flag, const Environment& environment) {
  const std::string name = environment_variable(flag.name);
  const auto value = environment(name);
  if (!value || value->empty()) return;
  try {
    if (!flag.takes_value) {
      if (switch_value(flag.name, *value)) flag.set(o, "");
    } else if (flag.repeatable) {
      for (const std::string& item : list_items(*value)) flag.set(o, item);
    } else {
      flag.set(o, *value);
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{} (from {})", e.what(), name));
  }
}

}  // namespace

int64_t default_max_memory_mb() {
  return std::max<int64_t>(1, machine_memory_bytes() / 2 >> 20);
}

Environment process_environment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* value = std::getenv(name.c_str());
    return value ? std::optional<std::string>(value) : std::nullopt;
  };
}

void load_auth_token(Options& options) {
  if (options.auth_token_file) options.auth_token = read_auth_token(*options.auth_token_file);
}

std::string environment_variable(std::string_view flag) {
  std::string name = "LIGHTPROBE_";
  for (const char c : flag) name += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

std::optional<Options> parse_options(int argc, char** argv, Options defaults,
                                     const Environment& environment) {
  Options o = std::move(defaults);
  std::vector<std::pair<const Flag*, std::string>> given;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << usage();
      return std::nullopt;
    }
    if (arg == "--version") {
      std::cout << "lightprobe-server " << LIGHTPROBE_VERSION << "\n";
      return std::nullopt;
    }
    if (arg == "--list-routes") {
      o.list_routes = true;
      continue;
    }
    if (arg == "--health-check") {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      o.health_check_url = argv[++i];
      parse_health_check_url(o.health_check_url);  // a malformed URL is a bad flag
      continue;
    }
    const Flag* flag = find_flag(arg);
    if (!flag) throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
    if (flag->takes_value && i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
    given.emplace_back(flag, flag->takes_value ? argv[++i] : "");
  }
  for (const Flag& f : flags())
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == &f; }))
      set_from_environment(o, f, environment);
  for (const auto& [flag, value] : given) flag->set(o, value);
  check_role(o);
  return o;
}

}  // namespace lp::server

#include "server/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "server/flag_parser.hpp"
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
                         0 if it answers 200, 1 otherwise (a container's HEALTHCHECK); a PATH alone
                         (/api/v1/ready) probes this configuration's --host and --port
  --version              print the version and exit
  --help                 print this help and exit
)";

constexpr const char* kEnvironmentHead = R"(
Environment: every flag but --list-routes, --health-check, --version and --help can be given as a variable
instead: LIGHTPROBE_ and its name in upper case, - written _ (--max-pixels: LIGHTPROBE_MAX_PIXELS). A flag on the
command line wins over its variable; an empty variable counts as unset; a repeatable flag's variable takes a
comma-separated list, a switch's 1, true, yes or 0, false, no. The variables:
)";

// A flag that takes text or is a switch.
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

void set_log_format(Options& o, const std::string& v) {
  o.log.format = parse_enum_flag<LogFormat>("log-format", v);
}

void set_render_priority(Options& o, const std::string& v) {
  o.jobs.render_priority = parse_enum_flag<RenderPriority>("render-priority", v);
}

void set_role(Options& o, const std::string& v) {
  o.scale_out.role = parse_enum_flag<ServerRole>("role", v);
}

// A server of one role only splits jobs with others, through Redis.
void check_role(const Options& o) {
  const ScaleOutConfig& s = o.scale_out;
  if (s.role != ServerRole::Both && !s.redis)
    throw std::invalid_argument(fmt::format("--role {} needs --redis redis://HOST:PORT", enum_name(s.role)));
}

const std::vector<TextFlag>& text_flags() {
  static const std::vector<TextFlag> flags = {
      {"host", "ADDR", "address to listen on (default 127.0.0.1)", false,
       [](Options& o, const std::string& v) { o.host = v; }},
      {"allowed-host", "NAME",
       "a Host header name to answer besides loopback and --host (repeatable); others\nget 403 (a "
       "defence against DNS rebinding)",
       true, [](Options& o, const std::string& v) { o.browser.allowed_hosts.push_back(v); }},
      {"cors-origin", "ORIGIN",
       "an origin (http://host:port, or *) whose pages may call the API (repeatable);\nwithout it, "
       "requests that change state from another origin get 403",
       true, [](Options& o, const std::string& v) { o.browser.cors_origins.push_back(v); }},
      {"trusted-proxy", "ADDR[/BITS]",
       "a reverse proxy whose X-Forwarded-For names the client (repeatable): its\nconnections are not "
       "limited per client, its requests are, by the forwarded client",
       true, [](Options& o, const std::string& v) { o.transport.trusted_proxies.add(v); }},
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
      {"denoise-weights", "DIR",
       "the denoiser's weights, Open Image Denoise's rt_*.tza files, for renders with\n\"denoise\" "
       "(default: the installed ones, else the source tree's engine/denoise/weights)",
       false, [](Options& o, const std::string& v) { o.denoise_weights = v; }},
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
       "redis://[USER:PASSWORD@]HOST[:PORT][/DB] (rediss:// for TLS): split renders into\nwork items of "
       "sample ranges on Redis Streams, rendered by every server of that Redis\n(see --role)",
       false, [](Options& o, const std::string& v) { o.scale_out.redis = parse_redis_url(v); }},
      {"redis-password-file", "FILE",
       std::string("the password of --redis is the text FILE holds (or the variable ") +
           kRedisPasswordVariable + ",\nnever a flag; or in the URL)",
       false, [](Options& o, const std::string& v) { o.scale_out.redis_password_file = v; }},
      {"redis-tls-ca", "FILE",
       "with rediss://, the PEM certificates of the CAs that sign Redis's certificate\n(default: the "
       "system's CA store)",
       false, [](Options& o, const std::string& v) { o.scale_out.redis_tls.ca = v; }},
      {"redis-tls-cert", "FILE",
       "with rediss://, a PEM client certificate, for a Redis that verifies clients", false,
       [](Options& o, const std::string& v) { o.scale_out.redis_tls.cert = v; }},
      {"redis-tls-key", "FILE", "with rediss://, the PEM private key of --redis-tls-cert", false,
       [](Options& o, const std::string& v) { o.scale_out.redis_tls.key = v; }},
      {"role", "NAME",
       enum_names_joined<ServerRole>("|") +
           " with --redis: accept renders and merge their items, render items, or\nboth (default both)",
       false, set_role},
      {"advertise-url", "URL",
       "with --redis, where workers fetch this server's maps (default\nhttp://HOST:PORT of --host and the "
       "port)",
       false, [](Options& o, const std::string& v) { o.scale_out.advertise_url = v; }},
      {"log-level", "NAME", "least severe messages written: " + log_level_names() + " (default info)", false,
       [](Options& o, const std::string& v) { o.log.level = parse_log_level(v); }},
      {"log-format", "NAME",
       enum_names_joined<LogFormat>("|") +
           ": lines for people, or one JSON object a line (time, level, message; access\nlines also "
           "request_id, method, path, route, status, duration_ms, client)\n(default text)",
       false, set_log_format},
  };
  return flags;
}

// An integer flag: its declaration (with the subsystem that owns it) and where its value goes.
struct IntFlag {
  const api::IntParameter* parameter;
  void (*set)(Options&, int64_t);
};

// In --help order.
const std::vector<IntFlag>& int_flags() {
  using S = std::chrono::seconds;
  static const std::vector<IntFlag> flags = {
      {&kPort, [](Options& o, int64_t v) { o.port = int(v); }},
      {&api::kThreads, [](Options& o, int64_t v) { o.threads = int(v); }},
      {&kMaxUploadMb, [](Options& o, int64_t v) { o.transport.max_body = uint64_t(v) << 20; }},
      {&api::kMaxPixels, [](Options& o, int64_t v) { o.limits.max_pixels = v; }},
      {&api::kMaxSamples, [](Options& o, int64_t v) { o.limits.max_samples = v; }},
      {&kMaxEnvmaps, [](Options& o, int64_t v) { o.max_envmaps = v; }},
      {&api::kMaxLights, [](Options& o, int64_t v) { o.limits.max_lights = v; }},
      {&kMaxAssets, [](Options& o, int64_t v) { o.assets.max_assets = v; }},
      {&kMaxAssetMb, [](Options& o, int64_t v) { o.assets.max_asset_mb = v; }},
      {&kMaxAssetFiles, [](Options& o, int64_t v) { o.assets.max_asset_files = v; }},
      {&kMaxMemoryMb, [](Options& o, int64_t v) { o.max_memory_mb = v; }},
      {&api::kMaxRenderWidth, [](Options& o, int64_t v) { o.limits.max_render_width = v; }},
      {&api::kMaxRenderHeight, [](Options& o, int64_t v) { o.limits.max_render_height = v; }},
      {&api::kMaxRenderSpp, [](Options& o, int64_t v) { o.limits.max_render_spp = v; }},
      {&api::kMaxRenderDepth, [](Options& o, int64_t v) { o.limits.max_render_depth = v; }},
      {&api::kMaxRenderObjects, [](Options& o, int64_t v) { o.limits.max_render_objects = v; }},
      {&api::kMaxMeshTriangles, [](Options& o, int64_t v) { o.limits.max_mesh_triangles = v; }},
      {&api::kMaxTexturePixels, [](Options& o, int64_t v) { o.limits.max_texture_pixels = v; }},
      {&api::kMaxModelTexturePixels, [](Options& o, int64_t v) { o.limits.max_model_texture_pixels = v; }},
      {&kMaxRunningJobs, [](Options& o, int64_t v) { o.jobs.max_running = int(v); }},
      {&kMaxQueuedJobs, [](Options& o, int64_t v) { o.jobs.max_queued = int(v); }},
      {&kMaxPrefiltersPerClient, [](Options& o, int64_t v) { o.jobs.max_per_client = int(v); }},
      {&kMaxFinishedJobs, [](Options& o, int64_t v) { o.jobs.max_finished = int(v); }},
      {&kMaxFinishedMb, [](Options& o, int64_t v) { o.jobs.max_finished_bytes = v << 20; }},
      {&kMaxEventStreams, [](Options& o, int64_t v) { o.max_event_streams = int(v); }},
      {&kMaxConnections, [](Options& o, int64_t v) { o.transport.max_connections = int(v); }},
      {&kMaxConnectionsPerClient,
       [](Options& o, int64_t v) { o.transport.max_connections_per_client = int(v); }},
      {&kHeaderTimeoutS, [](Options& o, int64_t v) { o.transport.header_timeout = S(v); }},
      {&kIoTimeoutS, [](Options& o, int64_t v) { o.transport.io_timeout = S(v); }},
      {&kKeepAliveTimeoutS, [](Options& o, int64_t v) { o.transport.keep_alive_timeout = S(v); }},
      {&kShutdownGraceS, [](Options& o, int64_t v) { o.shutdown_grace_s = int(v); }},
      {&kAccessLogSample, [](Options& o, int64_t v) { o.log.access_log_sample = v; }},
      {&kRedisItemSpp, [](Options& o, int64_t v) { o.scale_out.item_spp = int(v); }},
      {&kRedisClaimTimeoutS, [](Options& o, int64_t v) { o.scale_out.claim_timeout_s = int(v); }},
  };
  return flags;
}

// Every flag that sets an option, the text flags first, each setting its option in `o`.
std::vector<Flag> flags_of(Options& o) {
  std::vector<Flag> out;
  for (const TextFlag& f : text_flags())
    out.push_back({f.name, f.value ? f.value : "", f.help, f.repeatable,
                   [&o, set = f.set](const std::string& v) { set(o, v); }});
  for (const IntFlag& f : int_flags()) {
    const api::IntParameter& p = *f.parameter;
    const std::string fallback = p.default_text ? p.default_text : std::to_string(p.fallback);
    out.push_back(
        {p.flag, "N", fmt::format("{} (default {})", p.help, fallback), false,
         [&o, &p, set = f.set](const std::string& v) { set(o, parse_integer_flag(p.flag, v, p.range)); }});
  }
  return out;
}

// The text flags, the actions, then the numbers.
std::string usage() {
  Options unused;
  const std::vector<Flag> flags = flags_of(unused);
  std::string out = kUsageHead;
  for (size_t i = 0; i < flags.size(); ++i) {
    if (i == text_flags().size())
      out += fmt::format(fmt::runtime(kActions), fmt::arg("health_timeout", kHealthCheckTimeout.count())) +
             "\nNumbers:\n";
    out += help_entry(flags[i].usage(), flags[i].help);
  }
  return out + kEnvironmentHead + environment_list(flags);
}

}  // namespace

int64_t default_max_memory_mb() {
  return std::max<int64_t>(1, machine_memory_bytes() / 2 >> 20);
}

std::vector<const api::IntParameter*> int_flag_parameters() {
  std::vector<const api::IntParameter*> out;
  for (const IntFlag& f : int_flags()) out.push_back(f.parameter);
  return out;
}

void load_auth_token(Options& options) {
  if (options.auth_token_file) options.auth_token = read_auth_token(*options.auth_token_file);
}

std::optional<Options> parse_options(int argc, char** argv, Options defaults,
                                     const Environment& environment) {
  Options o = std::move(defaults);
  const std::vector<Action> actions = {
      {{"--help", "-h"},
       false,
       [](const std::string&) {
         std::cout << usage();
         return false;
       }},
      {{"--version"},
       false,
       [](const std::string&) {
         std::cout << "lightprobe-server " << LIGHTPROBE_VERSION << "\n";
         return false;
       }},
      {{"--list-routes"}, false, [&o](const std::string&) { return o.list_routes = true; }},
      {{"--health-check"},
       true,
       [&o](const std::string& url) {
         if (!url.starts_with('/')) parse_health_check_url(url);  // a malformed URL is a bad flag
         o.health_check_url = url;
         return true;
       }},
  };
  if (!parse_command_line(argc, argv, flags_of(o), actions, environment)) return std::nullopt;
  check_role(o);
  complete_redis(o.scale_out, environment(kRedisPasswordVariable));
  return o;
}

}  // namespace lp::server

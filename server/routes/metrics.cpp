// GET /metrics: the server's figures in the Prometheus text format (observability/prometheus_text.hpp).
#include <array>
#include <map>
#include <utility>

#include "server/http/request_context.hpp"
#include "server/observability/process_stats.hpp"
#include "server/observability/prometheus_text.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
namespace {

void write_envmaps(const App& app, PrometheusText& out) {
  const auto maps = app.envmaps.list();
  int64_t bytes = 0;
  for (const auto& m : maps) bytes += m->map->memory_bytes();
  out.family("lightprobe_envmaps", "gauge", "Environment maps loaded.");
  out.sample("lightprobe_envmaps", {}, double(maps.size()));
  out.family("lightprobe_envmap_bytes", "gauge",
             "Bytes the loaded maps hold with their derived tables (their memory_bytes, summed).");
  out.sample("lightprobe_envmap_bytes", {}, double(bytes));
}

// A family of jobs by state, every state present.
void write_jobs(const JobManager& jobs, const std::string& name, const std::string& help,
                PrometheusText& out) {
  std::map<JobStatus, int> by_state;
  for (const auto& job : jobs.list()) ++by_state[job->status()];
  out.family(name, "gauge", help);
  for (const auto& e : enum_entries(JobStatus{}))
    out.sample(name, {{"state", e.name}}, double(by_state[e.value]));
}

void write_renders(const App& app, PrometheusText& out) {
  write_jobs(app.renders, "lightprobe_render_jobs",
             "Render jobs by state (finished ones as --max-finished-jobs keeps them).", out);
  write_jobs(app.prefilters, "lightprobe_prefilter_jobs",
             "Prefiltered-chain jobs by state (finished ones as --max-finished-jobs keeps them).", out);
  out.family("lightprobe_render_queue_depth", "gauge", "Renders waiting for a runner (--max-queued-jobs).");
  out.sample("lightprobe_render_queue_depth", {}, double(app.renders.queued_count()));
  const RenderCounters& c = app.render_counters;
  out.family(
      "lightprobe_render_samples_total", "counter",
      "Camera samples renders traced, counted at the end of each pass; rate() gives samples per second.");
  out.sample("lightprobe_render_samples_total", {}, double(c.samples.load()));
  out.family("lightprobe_render_rays_total", "counter",
             "Rays renders traced (camera, bounce, shadow), counted at the end of each pass.");
  out.sample("lightprobe_render_rays_total", {}, double(c.rays.load()));
  out.family("lightprobe_render_seconds_total", "counter",
             "Seconds renders spent in passes, summed over the renders running at once; samples_total / "
             "seconds_total is the rate of one render.");
  out.sample("lightprobe_render_seconds_total", {}, c.seconds.load());
}

void write_memory(const App& app, PrometheusText& out) {
  out.family("lightprobe_memory_budget_bytes", "gauge", "The memory budget, --max-memory-mb, in bytes.");
  out.sample("lightprobe_memory_budget_bytes", {}, double(app.memory.capacity()));
  out.family("lightprobe_memory_used_bytes", "gauge", "Bytes reserved from the memory budget, by use.");
  constexpr std::array<std::pair<MemoryUse, const char*>, 3> kUses = {
      {{MemoryUse::Held, "held"}, {MemoryUse::Transient, "transient"}, {MemoryUse::Cache, "cache"}}};
  for (const auto& [use, name] : kUses)
    out.sample("lightprobe_memory_used_bytes", {{"use", name}}, double(app.memory.used(use)));
}

// The standard process figures of Prometheus's client libraries.
void write_process(PrometheusText& out) {
  out.family("process_resident_memory_bytes", "gauge", "Resident memory size in bytes.");
  out.sample("process_resident_memory_bytes", {}, double(resident_memory_bytes()));
  out.family("process_virtual_memory_bytes", "gauge", "Virtual memory size in bytes.");
  out.sample("process_virtual_memory_bytes", {}, double(virtual_memory_bytes()));
  out.family("process_cpu_seconds_total", "counter", "Total user and system CPU time spent in seconds.");
  out.sample("process_cpu_seconds_total", {}, process_cpu_seconds());
  out.family("process_open_fds", "gauge", "Number of open file descriptors.");
  out.sample("process_open_fds", {}, double(open_file_descriptors()));
  out.family("process_max_fds", "gauge", "Maximum number of open file descriptors.");
  out.sample("process_max_fds", {}, double(max_file_descriptors()));
  out.family("process_start_time_seconds", "gauge",
             "Start time of the process since the Unix epoch in seconds.");
  out.sample("process_start_time_seconds", {}, process_start_time_s());
}

void write_server(const App& app, PrometheusText& out) {
  out.family("lightprobe_build_info", "gauge", "The server's version, as a label (the value is 1).");
  out.sample("lightprobe_build_info", {{"version", LIGHTPROBE_VERSION}}, 1);
  out.family("lightprobe_ready", "gauge", "1 once the maps and the state directory are loaded at start.");
  out.sample("lightprobe_ready", {}, app.ready.load() ? 1 : 0);
  out.family("lightprobe_http_requests_in_flight", "gauge",
             "Requests begun and not yet answered (this scrape among them).");
  out.sample("lightprobe_http_requests_in_flight", {}, double(requests_in_flight()));
  out.family("lightprobe_event_streams", "gauge", "Render event streams open (--max-event-streams).");
  out.sample("lightprobe_event_streams", {}, double(app.event_streams.load()));
}

}  // namespace

void register_metrics_routes(Router& router, App& app) {
  router.get("/metrics", [&app](const httplib::Request&, httplib::Response& res) {
    PrometheusText out;
    write_server(app, out);
    app.http_metrics.write(out);
    write_envmaps(app, out);
    write_renders(app, out);
    write_memory(app, out);
    write_process(out);
    res.set_content(out.text(), kPrometheusContentType);
  });
}

}  // namespace lp::server

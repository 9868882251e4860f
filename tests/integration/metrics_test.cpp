// GET /metrics of the real server, parsed as the Prometheus text format (0.0.4) is specified: HELP and
// TYPE lines before a family's samples, each family one group, valid names, labels and values, histogram
// buckets cumulative up to le="+Inf" = _count. Its figures are those of the requests, maps and render the
// test made, counted exactly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/http_reply.hpp"
#include "support/raw_connection.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using Labels = std::map<std::string, std::string>;

struct Sample {
  std::string name;
  Labels labels;
  double value = 0;
};

struct Exposition {
  std::map<std::string, std::string> types;  // family -> counter, gauge, histogram, ...
  std::vector<Sample> samples;

  // The value of the one sample `name` with exactly `labels`; NaN (and a test failure) if there is none.
  double value(const std::string& name, const Labels& labels = {}) const {
    for (const Sample& s : samples)
      if (s.name == name && s.labels == labels) return s.value;
    ADD_FAILURE() << "no sample " << name;
    return std::nan("");
  }
};

// The family a sample belongs to: a histogram's _bucket, _sum and _count samples are its own.
std::string family_of(const std::string& name, const std::map<std::string, std::string>& types) {
  for (const char* suffix : {"_bucket", "_sum", "_count"}) {
    const std::string s = suffix;
    if (name.size() > s.size() && name.ends_with(s)) {
      const std::string base = name.substr(0, name.size() - s.size());
      if (types.count(base) && types.at(base) == "histogram") return base;
    }
  }
  return name;
}

// Label values: \\, \" and \n are the only escapes.
Labels parse_labels(const std::string& text) {
  Labels labels;
  size_t i = 0;
  const std::regex name(R"([a-zA-Z_][a-zA-Z0-9_]*)");
  while (i < text.size()) {
    const size_t eq = text.find("=\"", i);
    EXPECT_NE(eq, std::string::npos) << text;
    if (eq == std::string::npos) return labels;
    const std::string key = text.substr(i, eq - i);
    EXPECT_TRUE(std::regex_match(key, name)) << key;
    std::string value;
    for (i = eq + 2; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] != '\\') {
        value += text[i];
        continue;
      }
      const char e = text[++i];
      EXPECT_TRUE(e == '\\' || e == '"' || e == 'n') << text;
      value += e == 'n' ? '\n' : e;
    }
    EXPECT_TRUE(labels.emplace(key, value).second) << "label " << key << " twice";
    i += 1;  // the closing quote
    if (i < text.size()) {
      EXPECT_EQ(text[i], ',') << text;
      ++i;
    }
  }
  return labels;
}

Exposition parse(const std::string& text) {
  Exposition out;
  EXPECT_TRUE(text.ends_with("\n"));
  const std::regex help(R"(# HELP ([a-zA-Z_:][a-zA-Z0-9_:]*) .*)");
  const std::regex type(R"(# TYPE ([a-zA-Z_:][a-zA-Z0-9_:]*) (counter|gauge|histogram|summary|untyped))");
  const std::regex sample(R"(([a-zA-Z_:][a-zA-Z0-9_:]*)(\{(.*)\})? (\S+))");
  std::set<std::string> helped, ended;
  std::string current;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    SCOPED_TRACE(line);
    std::smatch m;
    std::string family;
    if (std::regex_match(line, m, help)) {
      family = m[1];
      EXPECT_TRUE(helped.insert(family).second) << "a second HELP";
    } else if (std::regex_match(line, m, type)) {
      family = m[1];
      EXPECT_TRUE(out.types.emplace(family, m[2]).second) << "a second TYPE";
    } else {
      if (!std::regex_match(line, m, sample)) {
        ADD_FAILURE() << "not a sample line";
        continue;
      }
      Sample s{m[1], parse_labels(m[3]), 0};
      const std::string v = m[4];
      s.value = v == "+Inf" ? INFINITY : v == "-Inf" ? -INFINITY : std::stod(v);
      family = family_of(s.name, out.types);
      EXPECT_TRUE(out.types.count(family)) << "a sample before its TYPE line";
      out.samples.push_back(std::move(s));
    }
    if (family != current) {
      EXPECT_FALSE(ended.count(family)) << family << " is not one group";
      if (!current.empty()) ended.insert(current);
      current = family;
    }
  }
  return out;
}

// Every histogram's buckets, per label set: le rising to +Inf, counts not falling, +Inf = _count.
void check_histograms(const Exposition& e) {
  for (const auto& [family, type] : e.types) {
    if (type != "histogram") continue;
    std::map<Labels, std::vector<std::pair<double, double>>> buckets;
    for (const Sample& s : e.samples)
      if (s.name == family + "_bucket") {
        Labels without = s.labels;
        const double le = s.labels.at("le") == "+Inf" ? INFINITY : std::stod(s.labels.at("le"));
        without.erase("le");
        buckets[without].emplace_back(le, s.value);
      }
    EXPECT_FALSE(buckets.empty()) << family;
    for (const auto& [labels, list] : buckets) {
      for (size_t i = 1; i < list.size(); ++i) {
        EXPECT_LT(list[i - 1].first, list[i].first) << family;
        EXPECT_LE(list[i - 1].second, list[i].second) << family;
      }
      EXPECT_TRUE(std::isinf(list.back().first)) << family;
      EXPECT_EQ(list.back().second, e.value(family + "_count", labels)) << family;
      EXPECT_GE(e.value(family + "_sum", labels), 0) << family;
    }
  }
}

int64_t resident_bytes_of(int pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  int64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * 4096;
}

TEST(Metrics, ThePrometheusTextFormatWithTheServersFigures) {
  test::ServerProcess s;
  auto c = s.client();
  // One connection: the server counts a request after sending its response, so a request on another
  // connection could be answered before the last one is counted; on the same one it cannot.
  c->set_keep_alive(true);
  for (int i = 0; i < 3; ++i) ASSERT_EQ(c->Get("/api/v1/health")->status, 200);
  for (int i = 0; i < 2; ++i) ASSERT_EQ(c->Get("/api/v1/envmaps/default")->status, 200);
  ASSERT_EQ(c->Get("/api/v1/envmaps/absent")->status, 404);
  ASSERT_EQ(c->Get("/no/such/path")->status, 404);
  ASSERT_EQ(c->Get("/")->status, 200);  // the dashboard
  const json render = {
      {"envmap", "default"}, {"scene", {{"preset", "sphere"}}}, {"width", 16}, {"height", 16}, {"spp", 4}};
  const auto submitted = test::reply(c->Post("/api/v1/renders", render.dump(), "application/json"));
  ASSERT_EQ(submitted.status, 202) << submitted.body;
  const json done = test::finished_render(*c, submitted.body_json()["id"]);
  ASSERT_EQ(done["status"], "done") << done;
  const json map = test::reply(c->Get("/api/v1/envmaps/default")).body_json();
  const json health = test::reply(c->Get("/api/v1/health")).body_json();

  const test::Reply r = test::reply(c->Get("/metrics"));
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.type(), "text/plain; version=0.0.4; charset=utf-8");
  const Exposition e = parse(r.body);
  check_histograms(e);

  const std::string requests = "lightprobe_http_requests_total";
  EXPECT_EQ(e.types.at(requests), "counter");
  // Health: 3 and the one read for the budget; maps: 2, the one read for its bytes, and 1 not found.
  EXPECT_EQ(e.value(requests, {{"method", "GET"}, {"route", "/api/v1/health"}, {"status", "200"}}), 4);
  EXPECT_EQ(e.value(requests, {{"method", "GET"}, {"route", "/api/v1/envmaps/{id}"}, {"status", "200"}}), 3);
  EXPECT_EQ(e.value(requests, {{"method", "GET"}, {"route", "/api/v1/envmaps/{id}"}, {"status", "404"}}), 1);
  EXPECT_EQ(e.value(requests, {{"method", "GET"}, {"route", "none"}, {"status", "404"}}), 1);
  EXPECT_EQ(e.value(requests, {{"method", "GET"}, {"route", "static"}, {"status", "200"}}), 1);
  EXPECT_EQ(e.value(requests, {{"method", "POST"}, {"route", "/api/v1/renders"}, {"status", "202"}}), 1);
  const std::string latency = "lightprobe_http_request_duration_seconds";
  EXPECT_EQ(e.types.at(latency), "histogram");
  EXPECT_EQ(e.value(latency + "_count", {{"method", "GET"}, {"route", "/api/v1/health"}}), 4);
  EXPECT_EQ(e.value(latency + "_count", {{"method", "GET"}, {"route", "/api/v1/envmaps/{id}"}}), 4);

  EXPECT_EQ(e.value("lightprobe_envmaps"), 1);
  EXPECT_EQ(e.value("lightprobe_envmap_bytes"), map["memory_bytes"].get<double>());
  EXPECT_EQ(e.value("lightprobe_render_jobs", {{"state", "done"}}), 1);
  for (const char* state : {"queued", "running", "failed", "cancelled", "interrupted"})
    EXPECT_EQ(e.value("lightprobe_render_jobs", {{"state", state}}), 0) << state;
  EXPECT_EQ(e.value("lightprobe_render_queue_depth"), 0);
  EXPECT_EQ(e.types.at("lightprobe_render_samples_total"), "counter");
  EXPECT_EQ(e.value("lightprobe_render_samples_total"), 16 * 16 * 4);
  EXPECT_EQ(e.value("lightprobe_render_samples_total"), done["samples"].get<double>());
  EXPECT_EQ(e.value("lightprobe_render_rays_total"), done["rays"].get<double>());
  EXPECT_GE(e.value("lightprobe_render_rays_total"), 16 * 16 * 4);
  EXPECT_GT(e.value("lightprobe_render_seconds_total"), 0);
  EXPECT_NEAR(e.value("lightprobe_render_samples_total") / e.value("lightprobe_render_seconds_total"),
              done["samples_per_s"].get<double>(), 1e-6 * done["samples_per_s"].get<double>());
  EXPECT_EQ(e.value("lightprobe_memory_budget_bytes"), health["memory"]["budget_bytes"].get<double>());
  EXPECT_EQ(e.value("lightprobe_ready"), 1);
  EXPECT_EQ(e.value("lightprobe_build_info", {{"version", health["version"].get<std::string>()}}), 1);

  // Resident memory, against the kernel's figure read now (it moves a little between the two reads).
  const double rss = e.value("process_resident_memory_bytes");
  EXPECT_NEAR(rss, double(resident_bytes_of(s.pid())), 0.1 * rss);
  EXPECT_GT(rss, 10e6);  // the default map alone holds 6 MB of pixels
}

// /proc/PID/stat's user and system time (fields 14 and 15), in seconds.
double cpu_seconds_of(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));  // after the command name
  std::string field;
  double ticks = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i)
    if (i >= 14) ticks += std::stod(field);
  return ticks / double(sysconf(_SC_CLK_TCK));
}

int64_t open_fds_of(int pid) {
  const auto dir = "/proc/" + std::to_string(pid) + "/fd";
  return std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator());
}

// The soft "Max open files" of /proc/PID/limits.
double max_fds_of(int pid) {
  std::ifstream limits("/proc/" + std::to_string(pid) + "/limits");
  for (std::string line; std::getline(limits, line);)
    if (line.rfind("Max open files", 0) == 0) return std::stod(line.substr(26));
  return -1;
}

TEST(Metrics, ProcessFiguresPrefilterJobsAndRequestsInFlight) {
  test::ServerProcess s;
  auto c = s.client();
  ASSERT_EQ(test::upload_white_map(*c, "white").status, 201);
  const auto submitted = test::reply(c->Post(
      "/api/v1/envmaps/white/prefilter", R"({"levels":3,"base_size":16,"samples":16})", "application/json"));
  ASSERT_EQ(submitted.status, 202) << submitted.body;
  ASSERT_EQ(test::finished_job(*c, submitted.header("Location"))["status"], "done");
  // Two requests in flight besides the scrape: their bodies have not arrived.
  std::vector<std::unique_ptr<test::RawConnection>> held;
  for (int i = 0; i < 2; ++i) {
    held.push_back(std::make_unique<test::RawConnection>(s.port()));
    held.back()->send(
        "POST /api/v1/renders HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        "Content-Length: 2\r\n\r\n");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));

  const Exposition e = parse(test::reply(c->Get("/metrics")).body);
  EXPECT_EQ(e.value("lightprobe_http_requests_in_flight"), 3);
  EXPECT_EQ(e.types.at("lightprobe_prefilter_jobs"), "gauge");
  EXPECT_EQ(e.value("lightprobe_prefilter_jobs", {{"state", "done"}}), 1);
  for (const char* state : {"queued", "running", "failed", "cancelled", "interrupted"})
    EXPECT_EQ(e.value("lightprobe_prefilter_jobs", {{"state", state}}), 0) << state;
  // Against the kernel's figures read now; CPU time grows between the reads (2 cores, 10 ticks a read).
  EXPECT_EQ(e.types.at("process_cpu_seconds_total"), "counter");
  const double cpu = e.value("process_cpu_seconds_total");
  EXPECT_GT(cpu, 0);
  EXPECT_LE(cpu, cpu_seconds_of(s.pid()) + 0.1);
  EXPECT_NEAR(e.value("process_open_fds"), double(open_fds_of(s.pid())), 4);
  EXPECT_GE(e.value("process_open_fds"), 3 + 3);  // stdio, the listening socket and these connections
  EXPECT_EQ(e.value("process_max_fds"), max_fds_of(s.pid()));
  EXPECT_GT(e.value("process_virtual_memory_bytes"), e.value("process_resident_memory_bytes"));

  for (auto& h : held) h->send("{}");
  for (auto& h : held) EXPECT_NE(h->read_response().status, 0);
  // A request leaves the count just after its response is sent.
  double in_flight = 0;
  for (int i = 0; i < 100 && in_flight != 1; ++i, std::this_thread::sleep_for(std::chrono::milliseconds(10)))
    in_flight = parse(test::reply(c->Get("/metrics")).body).value("lightprobe_http_requests_in_flight");
  EXPECT_EQ(in_flight, 1);
}

TEST(Metrics, OnlyDeclaredQueryParametersAndNoRawPaths) {
  test::ServerProcess s;
  auto c = s.client();
  for (int i = 0; i < 20; ++i) c->Get(("/api/v1/envmaps/map" + std::to_string(i)).c_str());
  const std::string text = test::reply(c->Get("/metrics")).body;
  EXPECT_EQ(text.find("map7"), std::string::npos) << "a raw path is a label value";
  EXPECT_EQ(test::reply(c->Get("/metrics?debug=1")).status, 400);
}

}  // namespace
}  // namespace lp

// Renders split over machines through Redis Streams: a real redis-server on loopback, a coordinator
// (--role api) and worker processes (--role worker), each a real lightprobe-server. The split image is
// compared with the same render by one process without Redis: the same per-pixel samples, so equal
// within float rounding of the sums (1e-5 relative); a sample counted twice or lost would change it far
// more, and spp_done and samples say every pixel got exactly spp samples.
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "support/archive_builder.hpp"
#include "support/held_port.hpp"
#include "support/poll_until.hpp"
#include "support/redis_process.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"
#include "support/thread_sched.hpp"

namespace lp {
namespace {

using json = nlohmann::json;
using namespace std::chrono_literals;

constexpr int kSize = 96;

std::string body(int spp, int seed, const std::string& envmap = "default") {
  return json{{"envmap", envmap}, {"scene", {{"preset", "materials"}}},
              {"width", kSize},   {"height", kSize},
              {"spp", spp},       {"seed", seed}}
      .dump();
}

std::string submit(const test::ServerProcess& s, const std::string& request) {
  const auto r = s.client()->Post("/api/v1/renders", request, "application/json");
  EXPECT_TRUE(r && r->status == 202) << (r ? r->body : "no answer");
  return r && r->status == 202 ? json::parse(r->body)["id"].get<std::string>() : "";
}

json status(const test::ServerProcess& s, const std::string& id) {
  const auto r = s.client()->Get("/api/v1/renders/" + id);
  return r && r->status == 200 ? json::parse(r->body) : json{{"status", "?"}};
}

template <class Pred>
json poll(const test::ServerProcess& s, const std::string& id, Pred done) {
  return test::poll_until(
      "render " + id, [&] { return status(s, id); }, done);
}

json wait_finished(const test::ServerProcess& s, const std::string& id) {
  return poll(s, id, test::job_ended);
}

Image image(const test::ServerProcess& s, const std::string& id) {
  const auto r = s.client()->Get("/api/v1/renders/" + id + "/image?format=pfm");
  if (!r || r->status != 200) return {};
  return read_image({reinterpret_cast<const uint8_t*>(r->body.data()), r->body.size()}).image;
}

// The render by one process without Redis.
Image single_process_image(const std::string& request) {
  auto& s = test::default_server();
  const std::string id = submit(s, request);
  EXPECT_EQ(wait_finished(s, id)["status"], "done");
  return image(s, id);
}

double max_relative_difference(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height() || a.empty()) return 1e30;
  double worst = 0;
  for (size_t i = 0; i < a.data().size(); ++i)
    worst = std::max(worst, double(std::abs(a.data()[i] - b.data()[i])) / (1e-3 + std::abs(a.data()[i])));
  return worst;
}

void expect_whole(const json& st, int spp) {
  EXPECT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["spp_done"], spp);
  EXPECT_EQ(st["samples"], uint64_t(spp) * kSize * kSize);  // every pixel exactly spp samples
}

int count_lines(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Cluster {
  test::RedisProcess redis;
  std::vector<std::string> common;
  std::unique_ptr<test::ServerProcess> api;
  std::vector<std::unique_ptr<test::ServerProcess>> workers;

  // `api_flags` and `worker_flags` are added to the api server's and to each worker's.
  Cluster(int workers_count, int item_spp, int claim_timeout_s = 30, std::vector<std::string> api_flags = {},
          const std::vector<std::string>& worker_flags = {}) {
    common = {"--redis",
              redis.url(),
              "--redis-item-spp",
              std::to_string(item_spp),
              "--redis-claim-timeout-s",
              std::to_string(claim_timeout_s)};
    api_flags.insert(api_flags.end(), {"--role", "api"});
    api = std::make_unique<test::ServerProcess>(with(api_flags));
    for (int i = 0; i < workers_count; ++i) add_worker(worker_flags);
  }

  void add_worker(std::vector<std::string> flags = {}) {
    flags.insert(flags.end(), {"--role", "worker", "--threads", "1"});
    workers.push_back(std::make_unique<test::ServerProcess>(with(flags)));
  }

 private:
  std::vector<std::string> with(std::vector<std::string> flags) const {
    flags.insert(flags.end(), common.begin(), common.end());
    return flags;
  }
};

// A sample without labels of the server's /metrics; -1 if it has none.
double metric(const test::ServerProcess& s, const std::string& name) {
  const auto r = s.client()->Get("/metrics");
  if (!r || r->status != 200) return -1;
  std::smatch m;
  if (!std::regex_search(r->body, m, std::regex("\n" + name + " ([-0-9.e+]+)\n"))) return -1;
  return std::stod(m[1]);
}

TEST(RedisScaleOut, ThreeWorkersGiveTheImageOfOneProcess) {
  SKIP_WITHOUT_REDIS();
  const std::string request = body(48, 7);
  const Image reference = single_process_image(request);
  Cluster cluster(3, 4);
  const std::string id = submit(*cluster.api, request);
  expect_whole(wait_finished(*cluster.api, id), 48);
  EXPECT_LT(max_relative_difference(reference, image(*cluster.api, id)), 1e-5);
  // Which worker takes which item is the scheduler's; the job must have been shared.
  int items = 0, working = 0;
  for (const auto& w : cluster.workers) {
    const int n = count_lines(w->log(), "render " + id + " samples");
    working += n > 0;
    items += n;
  }
  EXPECT_GE(working, 2) << "one worker took every item";
  EXPECT_GE(items, 2 * 12);  // 12 items, each started and done
  // The api server's and the workers' metrics tell the same: 12 items out and merged, 3 workers alive.
  EXPECT_EQ(metric(*cluster.api, "lightprobe_redis_items_published_total"), 12);
  EXPECT_EQ(metric(*cluster.api, "lightprobe_redis_items_merged_total"), 12);
  EXPECT_EQ(metric(*cluster.api, "lightprobe_redis_items_outstanding"), 0);
  EXPECT_EQ(metric(*cluster.api, "lightprobe_redis_workers"), 3);
  double rendered = 0;
  for (const auto& w : cluster.workers) rendered += metric(*w, "lightprobe_redis_items_rendered_total");
  EXPECT_GE(rendered, 12);
  EXPECT_EQ(count_lines(cluster.api->log(), "fetched map"), 0);
  for (const auto& w : cluster.workers) EXPECT_EQ(count_lines(w->log(), "fetched map"), 0);  // all hold it
}

// docker/compose.scale-out.yaml's commands, on loopback: the api and worker services' flags (after the
// flags the image's entrypoint gives: host, port, folders) with the service names mapped to loopback
// addresses and each worker's state folder to one of its own; Redis keeps an append-only file as the
// restart test needs. Three workers and the api server render a job to the single-process image.
std::vector<std::string> compose_command(const YAML::Node& compose, const std::string& service,
                                         const std::map<std::string, std::string>& mapped) {
  std::vector<std::string> out;
  for (const auto& arg : compose["services"][service]["command"]) {
    const auto text = arg.as<std::string>();
    out.push_back(mapped.contains(text) ? mapped.at(text) : text);
  }
  return out;
}

TEST(RedisScaleOut, TheComposeFilesCommandsRenderAJobOverThreeWorkers) {
  SKIP_WITHOUT_REDIS();
  const YAML::Node compose = YAML::LoadFile(LIGHTPROBE_COMPOSE_SCALE_OUT);
  const auto redis_command = compose["services"]["redis"]["command"].as<std::vector<std::string>>();
  EXPECT_EQ(redis_command, (std::vector<std::string>{"redis-server", "--appendonly", "yes"}));
  test::RedisProcess redis;
  int api_port = 0;
  {
    test::HeldPort free(test::HeldPort::Mode::BoundOnly);
    api_port = free.port();
  }
  const std::string api_url = "http://127.0.0.1:" + std::to_string(api_port);
  std::vector<std::unique_ptr<test::TempDir>> worker_states;
  std::vector<std::unique_ptr<test::ServerProcess>> workers;
  std::map<std::string, std::string> mapped = {{"redis://redis:6379", redis.url()},
                                               {"http://api:8080", api_url}};
  auto api_flags = compose_command(compose, "api", mapped);
  api_flags.insert(api_flags.begin(), {"--port", std::to_string(api_port)});
  test::ServerProcess api(api_flags);
  for (int i = 0; i < 3; ++i) {
    worker_states.push_back(std::make_unique<test::TempDir>());
    mapped["/tmp/lightprobe-state"] = worker_states.back()->path().string();
    workers.push_back(std::make_unique<test::ServerProcess>(compose_command(compose, "worker", mapped)));
  }
  const std::string request = body(64, 19);
  const std::string id = submit(api, request);
  expect_whole(wait_finished(api, id), 64);
  EXPECT_LT(max_relative_difference(single_process_image(request), image(api, id)), 1e-5);
  int items = 0;
  for (const auto& w : workers) items += count_lines(w->log(), "render " + id + " samples");
  EXPECT_EQ(items, 2 * 4);  // 4 items of the default 16 spp, each started and done once
}

// The killed worker's heartbeat (a key that lives 3 s unless refreshed every second) ends, and the other
// worker takes its item then, not after the claim timeout (the default 30 s). Bound: the heartbeat's 3 s,
// a second's wait for new items and the rest of the item the other worker renders meanwhile, with margin.
// The claim timeout is an hour here, so only the dead worker's missing heartbeat can hand its item on
// within the test's wait; the time it took is printed (a few seconds: the heartbeat's lifetime).
TEST(RedisScaleOut, AWorkerKilledMidItemLeavesItToAnotherWithinSeconds) {
  SKIP_WITHOUT_REDIS();
  const std::string request = body(64, 11);
  const Image reference = single_process_image(request);
  Cluster cluster(2, 16, 3600);
  const std::string id = submit(*cluster.api, request);
  auto& victim = *cluster.workers[0];
  ASSERT_TRUE(victim.wait_log("render " + id + " samples")) << victim.log();
  victim.send_signal(SIGKILL);  // mid-item: an item takes far longer than the log poll
  const auto killed = std::chrono::steady_clock::now();
  ASSERT_TRUE(victim.wait_exit(10s).has_value());
  ASSERT_TRUE(cluster.workers[1]->wait_log("took over item", 1, 60s)) << cluster.workers[1]->log();
  const std::chrono::duration<double> taken_over = std::chrono::steady_clock::now() - killed;
  const json st = wait_finished(*cluster.api, id);
  const std::chrono::duration<double> finished = std::chrono::steady_clock::now() - killed;
  std::cout << "kill to take-over " << taken_over.count() << " s, to the render done " << finished.count()
            << " s\n";
  EXPECT_GE(metric(*cluster.workers[1], "lightprobe_redis_items_taken_over_total"), 1);
  EXPECT_EQ(metric(*cluster.api, "lightprobe_redis_workers"), 1);
  expect_whole(st, 64);
  EXPECT_LT(max_relative_difference(reference, image(*cluster.api, id)), 1e-5);
}

TEST(RedisScaleOut, ARenderSurvivesRedisRestarting) {
  SKIP_WITHOUT_REDIS();
  const std::string request = body(64, 5);
  const Image reference = single_process_image(request);
  Cluster cluster(1, 2);
  const std::string id = submit(*cluster.api, request);
  ASSERT_TRUE(cluster.workers[0]->wait_log("render " + id + " samples", 3));
  EXPECT_LT(status(*cluster.api, id)["spp_done"], 64);
  cluster.redis.restart();  // its append-only file keeps the items, partials and notices
  const json st = wait_finished(*cluster.api, id);
  expect_whole(st, 64);
  EXPECT_LT(max_relative_difference(reference, image(*cluster.api, id)), 1e-5);
}

TEST(RedisScaleOut, ARenderSurvivesRedisLosingEveryWrite) {
  SKIP_WITHOUT_REDIS();
  const std::string request = body(192, 13);
  const Image reference = single_process_image(request);
  Cluster cluster(2, 4);
  const std::string id = submit(*cluster.api, request);
  ASSERT_TRUE(cluster.workers[0]->wait_log("render " + id + " samples", 3));
  EXPECT_LT(status(*cluster.api, id)["spp_done"], 192);
  cluster.redis.restart_empty();  // no description, items, group, partials or notices
  const json st = wait_finished(*cluster.api, id);
  expect_whole(st, 192);
  EXPECT_LT(max_relative_difference(reference, image(*cluster.api, id)), 1e-5);
  EXPECT_GE(count_lines(cluster.api->log(), "issued again"), 1) << cluster.api->log();
}

TEST(RedisScaleOut, AWorkerRendersItemsAtTheRenderPriorityAndTakesNoRenderOfItsOwn) {
  SKIP_WITHOUT_REDIS();
  Cluster cluster(0, 4096);
  test::ServerProcess worker({"--redis", cluster.redis.url(), "--role", "worker", "--threads", "2"});
  const auto refused = worker.client()->Post("/api/v1/renders", body(4, 1), "application/json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 409);
  EXPECT_EQ(json::parse(refused->body)["error"]["code"], "worker_only") << refused->body;
  const auto turntable = worker.client()->Post(
      "/api/v1/turntables",
      R"({"envmap": "white", "scene": {"objects": [{"type": "sphere"}]}, "width": 8, "height": 8,
          "spp": 1, "turntable": {"frames": 2}})",
      "application/json");
  ASSERT_TRUE(turntable);
  EXPECT_EQ(turntable->status, 409);
  EXPECT_EQ(json::parse(turntable->body)["error"]["code"], "worker_only") << turntable->body;
  const std::string id = submit(*cluster.api, body(4096, 3));
  ASSERT_TRUE(worker.wait_log("render " + id + " samples")) << worker.log();
  std::this_thread::sleep_for(200ms);  // the arena's threads join the item
  const auto threads = test::threads_of(worker.pid());
  test::expect_render_threads_at(threads, {std::min(threads.main.nice + 10, 19), SCHED_OTHER}, 2);
  cluster.api->client()->Delete("/api/v1/renders/" + id);
}

// A split render the coordinator's stop interrupted goes on from the ranges it had merged: on Redis again
// after a restart, and on a server without Redis that renders the ranges left itself.
TEST(RedisScaleOut, AnInterruptedSplitRenderResumesFromTheRangesItMerged) {
  SKIP_WITHOUT_REDIS();
  constexpr int kSpp = 384;
  const std::string request = body(kSpp, 17);
  const Image reference = single_process_image(request);
  for (const bool with_redis : {true, false}) {
    SCOPED_TRACE(with_redis ? "resumed with Redis" : "resumed without Redis");
    test::TempDir state;
    const std::vector<std::string> kept = {"--state-dir", state.path().string(), "--resume-interrupted"};
    Cluster cluster(1, 8, 30, kept);
    const std::string id = submit(*cluster.api, request);
    const json before =
        poll(*cluster.api, id, [](const json& st) { return st["spp_done"] >= 48 || test::job_ended(st); });
    ASSERT_EQ(before["status"], "running") << before.dump();
    cluster.api->send_signal(SIGTERM);
    ASSERT_TRUE(cluster.api->wait_exit(30s).has_value());
    std::vector<std::string> flags = kept;
    if (with_redis) flags.insert(flags.end(), cluster.common.begin(), cluster.common.end());
    if (with_redis) flags.insert(flags.end(), {"--role", "api"});
    test::ServerProcess restarted(flags);
    const json st = wait_finished(restarted, id);
    expect_whole(st, kSpp);
    EXPECT_LT(max_relative_difference(reference, image(restarted, id)), 1e-5);
    EXPECT_EQ(count_lines(restarted.log(), with_redis ? "continues after" : "continues here after"), 1)
        << restarted.log();
  }
}

TEST(RedisScaleOut, CancelReachesEveryWorker) {
  SKIP_WITHOUT_REDIS();
  Cluster cluster(3, 4096);  // items far longer than the test: only a cancel ends them
  const std::string id = submit(*cluster.api, body(3 * 4096, 3));
  for (const auto& w : cluster.workers) ASSERT_TRUE(w->wait_log("render " + id + " samples")) << w->log();
  const auto r = cluster.api->client()->Delete("/api/v1/renders/" + id);
  ASSERT_TRUE(r && r->status == 202) << (r ? r->body : "no answer");
  EXPECT_EQ(wait_finished(*cluster.api, id)["status"], "cancelled");
  for (const auto& w : cluster.workers)
    EXPECT_TRUE(w->wait_log("cancelled", 1, 30s)) << "a worker went on rendering: " << w->log();
}

void upload_forest(const test::ServerProcess& s) {
  const auto bytes = test::read_bytes(test::envmap_path("forest.exr"));
  const auto r = s.client()->Post("/api/v1/envmaps?name=forest", reinterpret_cast<const char*>(bytes.data()),
                                  bytes.size(), "application/octet-stream");
  ASSERT_TRUE(r && r->status == 201) << (r ? r->body : "no answer");
}

// The bytes a server holds in its memory budget (GET /metrics).
int64_t held_bytes(const test::ServerProcess& s) {
  const auto r = s.client()->Get("/metrics");
  const std::string line = "lightprobe_memory_used_bytes{use=\"held\"} ";
  const size_t at = r && r->status == 200 ? r->body.find(line) : std::string::npos;
  return at == std::string::npos ? -1 : std::stoll(r->body.substr(at + line.size()));
}

TEST(RedisScaleOut, WorkersFetchAMapTheyLackByItsHashOnce) {
  SKIP_WITHOUT_REDIS();
  const std::string request = body(32, 9, "forest");
  test::ServerProcess single;
  upload_forest(single);
  const std::string single_id = submit(single, request);
  EXPECT_EQ(wait_finished(single, single_id)["status"], "done");
  Cluster cluster(2, 4);
  upload_forest(*cluster.api);  // the workers hold only the built-in map
  std::vector<int64_t> held_before;
  for (const auto& w : cluster.workers) held_before.push_back(held_bytes(*w));
  const std::string id = submit(*cluster.api, request);
  expect_whole(wait_finished(*cluster.api, id), 32);
  EXPECT_LT(max_relative_difference(image(single, single_id), image(*cluster.api, id)), 1e-5);
  for (size_t i = 0; i < cluster.workers.size(); ++i) {
    EXPECT_EQ(count_lines(cluster.workers[i]->log(), "fetched map"), 1) << cluster.workers[i]->log();
    // The fetched map's pixels are held in the worker's memory budget while it keeps the map.
    EXPECT_GE(held_bytes(*cluster.workers[i]) - held_before[i],
              EnvMap::image_bytes(test::kRealMapWidth, test::kRealMapHeight));
  }
  const auto unknown = cluster.api->client()->Get("/api/v1/content/0123456789abcdef-4x2");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404);
}

// The textured quad of tests/data/models/obj (an OBJ, its MTL, an albedo and a normal map) as an uploaded
// asset, and a render of an asset seen from above.
const std::vector<std::string> kQuadFiles = {"quad.obj", "quad.mtl", "checker.png", "flat_normal.png"};

std::string asset_body(int spp, int seed, const std::string& asset = "quad") {
  const json camera = {{"position", {0.5, 0.5, 3}}, {"look_at", {0.5, 0.5, 0}}, {"up", {0, 1, 0}}};
  const json quad = {{"type", "mesh"}, {"path", "assets/" + asset}};
  return json{{"envmap", "default"}, {"scene", {{"camera", camera}, {"objects", {quad}}}},
              {"width", kSize},      {"height", kSize},
              {"spp", spp},          {"seed", seed}}
      .dump();
}

std::string quad_file(const std::string& name) {
  const auto bytes = test::read_bytes(test::model_path("obj/" + name));
  return {bytes.begin(), bytes.end()};
}

void upload_quad(const test::ServerProcess& s) {
  std::vector<test::ArchiveMember> members;
  for (const auto& name : kQuadFiles) members.push_back(test::file_member(name, quad_file(name)));
  const auto r =
      s.client()->Post("/api/v1/assets?name=quad", test::make_archive(test::ArchiveFormat::Tar, members),
                       "application/octet-stream");
  ASSERT_TRUE(r && r->status == 201) << (r ? r->body : "no answer");
}

// The hash of the first mesh bundle a worker's log says it fetched.
std::string fetched_bundle(const std::string& log) {
  const std::string what = "fetched mesh bundle ";
  const size_t at = log.find(what);
  return at == std::string::npos
             ? ""
             : log.substr(at + what.size(), log.find(' ', at + what.size()) - at - what.size());
}

TEST(RedisScaleOut, WorkersFetchAMeshBundleTheyLackByItsHashOnce) {
  SKIP_WITHOUT_REDIS();
  const std::vector<std::pair<int, std::string>> renders = {{32, asset_body(32, 21)},
                                                            {16, asset_body(16, 22)}};
  test::ServerProcess single;
  upload_quad(single);
  std::vector<Image> references;
  for (const auto& [spp, request] : renders) {
    const std::string id = submit(single, request);
    EXPECT_EQ(wait_finished(single, id)["status"], "done");
    references.push_back(image(single, id));
  }
  // The workers hold neither the asset nor any file: their data and state directories are empty.
  test::TempDir api_data, data_a, data_b;
  Cluster cluster(0, 4, 30, {"--data-dir", api_data.path().string()});
  for (const auto* data : {&data_a, &data_b}) cluster.add_worker({"--data-dir", data->path().string()});
  upload_quad(*cluster.api);
  std::vector<std::string> ids;
  for (size_t i = 0; i < renders.size(); ++i) {
    ids.push_back(submit(*cluster.api, renders[i].second));
    expect_whole(wait_finished(*cluster.api, ids.back()), renders[i].first);
    EXPECT_LT(max_relative_difference(references[i], image(*cluster.api, ids.back())), 1e-5);
  }
  // Kept across items and renders: a worker that rendered fetched the bundle once.
  int working = 0;
  std::string hash;
  for (const auto& w : cluster.workers) {
    const std::string log = w->log();
    const bool rendered = count_lines(log, "render " + ids[0] + " samples") +
                              count_lines(log, "render " + ids[1] + " samples") >
                          0;
    working += rendered;
    EXPECT_EQ(count_lines(log, "fetched mesh bundle"), rendered ? 1 : 0) << log;
    if (rendered) hash = fetched_bundle(log);
  }
  EXPECT_GE(working, 1);
  const auto tar = cluster.api->client()->Get("/api/v1/content/" + hash);
  ASSERT_TRUE(tar && tar->status == 200) << hash;
  EXPECT_EQ(tar->get_header_value("Content-Type"), "application/x-tar");
  for (const auto& name : kQuadFiles) EXPECT_NE(tar->body.find(quad_file(name)), std::string::npos) << name;
}

TEST(RedisScaleOut, AMeshBundleThatDoesNotMatchItsHashIsRefused) {
  SKIP_WITHOUT_REDIS();
  test::TempDir api_state;
  Cluster cluster(0, 4, 30, {"--state-dir", api_state.path().string()});
  upload_quad(*cluster.api);
  const std::string id = submit(*cluster.api, asset_body(16, 3));
  ASSERT_TRUE(cluster.api->wait_log("work items of")) << cluster.api->log();
  // The texture changes after the render published its bundle's hash: the api server now sends files
  // of another content under that hash.
  std::ofstream(api_state.path() / "asset-files" / "quad" / "checker.png", std::ios::binary | std::ios::app)
      << "x";
  cluster.add_worker();
  const json st = wait_finished(*cluster.api, id);
  EXPECT_EQ(st["status"], "failed") << st.dump();
  const std::string message = st["error"].value("message", "");
  EXPECT_NE(message.find("does not match its hash"), std::string::npos) << message;
  EXPECT_TRUE(cluster.workers[0]->alive());
  EXPECT_EQ(count_lines(cluster.workers[0]->log(), "fetched mesh bundle"), 0);
}

TEST(RedisScaleOut, AWorkerRefusesAMeshBundleOverItsAssetLimit) {
  SKIP_WITHOUT_REDIS();
  Cluster cluster(1, 4, 30, {}, {"--max-asset-mb", "1", "--max-asset-files", "8"});
  const std::string grid = test::grid_obj(300);  // 2 MiB of OBJ text
  ASSERT_GT(grid.size(), size_t(2) << 20);
  const auto r = cluster.api->client()->Post(
      "/api/v1/assets?name=grid",
      test::make_archive(test::ArchiveFormat::Tar, {test::file_member("grid.obj", grid)}),
      "application/octet-stream");
  ASSERT_TRUE(r && r->status == 201) << (r ? r->body : "no answer");
  const json st = wait_finished(*cluster.api, submit(*cluster.api, asset_body(4, 1, "grid")));
  EXPECT_EQ(st["status"], "failed") << st.dump();
  const std::string message = st["error"].value("message", "");
  EXPECT_NE(message.find("the mesh bundle"), std::string::npos) << message;
  EXPECT_NE(message.find("is over"), std::string::npos) << message;
  EXPECT_TRUE(cluster.workers[0]->alive());
}

TEST(RedisScaleOut, ARoleWithoutRedisIsRefusedAtStart) {
  for (const char* role : {"api", "worker"}) {
    const auto failure = test::run_until_exit({"--role", role}, 30s);
    EXPECT_EQ(failure.exit_status, 2);
    EXPECT_NE(failure.output.find("--role " + std::string(role) + " needs --redis"), std::string::npos)
        << failure.output;
  }
  const auto bad_url = test::run_until_exit({"--redis", "http://127.0.0.1:6379"}, 30s);
  EXPECT_EQ(bad_url.exit_status, 2);
  EXPECT_NE(bad_url.output.find("redis://[USER:PASSWORD@]HOST[:PORT][/DB]"), std::string::npos)
      << bad_url.output;
}

}  // namespace
}  // namespace lp

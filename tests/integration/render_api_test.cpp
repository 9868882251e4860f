// Render jobs on the real server: submit, poll to done, images decode (and a furnace render matches its
// analytic value), image while running, cancel mid-render, server-sent events, a full queue (503 with
// Retry-After), bounded finished jobs, bad fields (400 naming the field), mesh paths outside the data dir,
// other requests answering while renders run, and SIGTERM with a render running (interrupted).
#include <gtest/gtest.h>
#include <stb_image.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/poll_until.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

// A data directory for the tests: meshes/bunny.obj (a copy) and escape.obj, a link to a file outside it.
class TempDataDir {
 public:
  TempDataDir() {
    fs::create_directories(path() / "meshes");
    fs::copy_file(test::mesh_path("bunny.obj"), path() / "meshes" / "bunny.obj");
    fs::create_symlink(test::mesh_path("bunny.obj"), path() / "escape.obj");
  }
  const fs::path& path() const { return dir_.path(); }

 private:
  test::TempDir dir_;
};

const fs::path& data_dir() {
  static TempDataDir dir;
  return dir.path();
}

// Default job limits (2 running), the forest map, the test data dir.
test::ServerProcess& render_server() {
  static test::ServerProcess server(
      {"--data-dir", data_dir().string(), "--load", "forest=" + test::envmap_path("forest.exr").string()});
  return server;
}

// One runner, one queue slot, two finished jobs kept, tiny meshes only; the built-in "default" map.
test::ServerProcess& small_server() {
  static test::ServerProcess server({"--data-dir", data_dir().string(), "--max-running-jobs", "1",
                                     "--max-queued-jobs", "1", "--max-finished-jobs", "2",
                                     "--max-mesh-triangles", "1000"});
  return server;
}

using test::reply;
using test::Reply;

Reply get(const test::ServerProcess& s, const std::string& path) {
  return reply(s.client()->Get(path.c_str()));
}
Reply del(const test::ServerProcess& s, const std::string& path) {
  return reply(s.client()->Delete(path.c_str()));
}
Reply post(const test::ServerProcess& s, const std::string& path, const json& body) {
  return reply(s.client()->Post(path.c_str(), body.dump(), "application/json"));
}

json render_body(const std::string& envmap, int width, int height, int spp,
                 json scene = {{"preset", "sphere"}}) {
  return {
      {"envmap", envmap}, {"scene", std::move(scene)}, {"width", width}, {"height", height}, {"spp", spp}};
}

// POST that must be accepted; returns the job id.
std::string submit(const test::ServerProcess& s, const json& body) {
  const Reply r = post(s, "/api/v1/renders", body);
  EXPECT_EQ(r.status, 202) << r.body;
  if (r.status != 202) return "";
  const json j = r.body_json();
  EXPECT_EQ(j["status"], "queued");
  EXPECT_EQ(r.header("Location"), "/api/v1/renders/" + j["id"].get<std::string>());
  return j["id"];
}

json status(const test::ServerProcess& s, const std::string& id) {
  const Reply r = get(s, "/api/v1/renders/" + id);
  EXPECT_EQ(r.status, 200) << r.body;
  return r.status == 200 ? r.body_json() : json{{"status", "?"}};
}

template <class Pred>
json poll(const test::ServerProcess& s, const std::string& id, Pred done) {
  return test::poll_until(
      "render " + id, [&] { return status(s, id); }, done);
}

bool finished(const json& st) {
  return st["status"] == "done" || st["status"] == "failed" || st["status"] == "cancelled";
}
json wait_finished(const test::ServerProcess& s, const std::string& id) {
  return poll(s, id, finished);
}

// Cancels a (big) render when the test leaves, however it leaves, and waits for it to stop.
class CancelOnExit {
 public:
  CancelOnExit(const test::ServerProcess& s, std::string id) : s_(s), id_(std::move(id)) {}
  ~CancelOnExit() {
    if (id_.empty()) return;
    del(s_, "/api/v1/renders/" + id_);
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < deadline) {
      const Reply r = get(s_, "/api/v1/renders/" + id_);
      if (r.status != 200 || finished(r.body_json())) return;
      std::this_thread::sleep_for(20ms);
    }
  }

 private:
  const test::ServerProcess& s_;
  std::string id_;
};

void expect_field_error(const Reply& r, const std::string& field) {
  EXPECT_EQ(r.status, 400) << r.body;
  if (r.status != 400) return;
  const json e = r.body_json()["error"];
  EXPECT_EQ(e["code"], "invalid_field") << r.body;
  EXPECT_EQ(e["message"].get<std::string>().rfind("field '" + field + "': ", 0), 0u) << r.body;
}

Image decode(const std::string& bytes) {
  return read_image({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}).image;
}

TEST(RenderApi, SubmitPollToDoneAndTheImageDecodesInEveryFormat) {
  auto& s = render_server();
  const std::string id = submit(s, render_body("forest", 32, 24, 4));
  ASSERT_FALSE(id.empty());
  const json st = wait_finished(s, id);
  ASSERT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["id"], id);
  EXPECT_EQ(st["progress"], 1.0);
  EXPECT_EQ(st["spp_done"], 4);
  EXPECT_EQ(st["spp"], 4);
  EXPECT_EQ(st["samples"], 32 * 24 * 4);
  EXPECT_GE(st["rays"].get<double>(), 32 * 24 * 4);
  EXPECT_GT(st["samples_per_s"].get<double>(), 0);
  EXPECT_GT(st["rays_per_s"].get<double>(), 0);
  EXPECT_GT(st["elapsed_s"].get<double>(), 0);
  EXPECT_TRUE(st["error"].is_null());

  for (const char* format : {"exr", "pfm"}) {
    const Reply r = get(s, "/api/v1/renders/" + id + "/image?format=" + format);
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_EQ(r.header("X-Spp-Done"), "4");
    const Image img = decode(r.body);
    ASSERT_EQ(img.width(), 32);
    ASSERT_EQ(img.height(), 24);
    EXPECT_GT(img.at(16, 12).y, 0.0f) << format;  // the lit sphere
  }
  const Reply png = get(s, "/api/v1/renders/" + id + "/image?format=png&exposure=1&gamma=2.2");
  ASSERT_EQ(png.status, 200) << png.body;
  EXPECT_EQ(png.header("Content-Type"), "image/png");
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.body.data()),
                                          int(png.body.size()), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, 32);
  EXPECT_EQ(h, 24);
  EXPECT_GT(pixels[(12 * 32 + 16) * 3 + 1], 0);
  stbi_image_free(pixels);

  const Reply list = get(s, "/api/v1/renders");
  ASSERT_EQ(list.status, 200);
  std::set<std::string> ids;
  const json all = list.body_json();
  for (const auto& j : all["renders"]) ids.insert(j["id"]);
  EXPECT_TRUE(ids.count(id));
}

// A sphere of albedo 0.5 under a constant map of radiance 1: the background is exactly 1 and every
// pixel on the sphere is 0.5 in expectation (a convex diffuse object sees only the map).
// A furnace render of 512 spp, sampled as `sampling` says: the job's answer, and the image checked
// against the analytic value.
json expect_furnace(const std::string& sampling) {
  auto& s = render_server();
  test::ensure_white_map(*s.client(), "constant");

  json body = render_body("constant", 32, 32, 512, {{"preset", "furnace"}});
  body["sampling"] = sampling;
  const std::string id = submit(s, body);
  const json job = wait_finished(s, id);
  EXPECT_EQ(job["status"], "done");
  if (job["status"] != "done") return job;
  const Reply r = get(s, "/api/v1/renders/" + id + "/image?format=pfm");
  EXPECT_EQ(r.status, 200);
  if (r.status != 200) return job;
  const Image img = decode(r.body);
  EXPECT_EQ(img.width(), 32);
  if (img.width() != 32) return job;
  for (int x : {0, 31})
    for (int y : {0, 31})
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(img.at(x, y)[c], 1.0f, 1e-5f) << x << "," << y;  // the map itself
  // The sphere spans ~11.3 px around the centre (radius 1 at distance 4, 40 degree field); average the
  // ~250 pixels within 9 px. Even sampling only the map (uniform, 2 cos / sample: std 0.65) gives a
  // standard error of 0.65 / sqrt(250 x 512) = 0.0018 for the mean, so 0.01 is over 5 sigma.
  double sum = 0;
  int n = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if (std::hypot(x + 0.5 - 16, y + 0.5 - 16) < 9) {
        sum += img.at(x, y).y;
        ++n;
      }
  EXPECT_GT(n, 200);
  EXPECT_NEAR(sum / n, 0.5, 0.01);
  return job;
}

TEST(RenderApi, FurnaceRenderThroughTheApiMatchesTheAnalyticValue) {
  EXPECT_EQ(expect_furnace("uniform")["sampling"], "uniform");
}

// Adaptive sampling moves samples between pixels: the furnace keeps its analytic value, spp stays the
// mean (a warm-up of 128 spp, then 384 spread by the pixels' noise).
TEST(RenderApi, AnAdaptiveFurnaceRenderMatchesTheAnalyticValue) {
  const json job = expect_furnace("adaptive");
  EXPECT_EQ(job["sampling"], "adaptive");
  EXPECT_EQ(job["spp_done"], 512);
  EXPECT_DOUBLE_EQ(job["progress"].get<double>(), 1.0);
  // The adaptive passes' counts are rounded stochastically: their total is 384 x 1024 in expectation.
  EXPECT_NEAR(job["samples"].get<double>() / (32.0 * 32.0), 512.0, 5.0);
}

TEST(RenderApi, TheImageIsAvailableWhileRunningAndCancelStopsTheRender) {
  auto& s = render_server();
  const std::string id = submit(s, render_body("forest", 512, 512, 4096));
  CancelOnExit guard(s, id);
  const json running =
      poll(s, id, [](const json& st) { return st["status"] == "running" && st["spp_done"] >= 1; });
  EXPECT_GT(running["progress"].get<double>(), 0.0);
  EXPECT_LT(running["progress"].get<double>(), 1.0);

  const Reply img = get(s, "/api/v1/renders/" + id + "/image?format=pfm");
  ASSERT_EQ(img.status, 200) << img.body;
  const int spp_in_image = std::stoi(img.header("X-Spp-Done"));
  EXPECT_GE(spp_in_image, 1);
  EXPECT_LT(spp_in_image, 4096);
  EXPECT_EQ(decode(img.body).width(), 512);

  const Reply cancel = del(s, "/api/v1/renders/" + id);
  ASSERT_EQ(cancel.status, 202) << cancel.body;
  EXPECT_TRUE(cancel.body_json()["cancel_requested"].get<bool>());
  const json st = wait_finished(s, id);
  EXPECT_EQ(st["status"], "cancelled");
  EXPECT_LT(st["spp_done"].get<int>(), 4096);
  EXPECT_TRUE(st["error"].is_null());
  EXPECT_EQ(get(s, "/api/v1/renders/" + id + "/image").status, 200);  // the passes that finished

  EXPECT_EQ(del(s, "/api/v1/renders/" + id).status, 204);  // a finished job is removed
  EXPECT_EQ(get(s, "/api/v1/renders/" + id).status, 404);
  EXPECT_EQ(del(s, "/api/v1/renders/" + id).status, 404);
}

struct Event {
  std::string name;
  json data;
};

std::vector<Event> parse_events(const std::string& text) {
  std::vector<Event> events;
  std::istringstream in(text);
  std::string line;
  Event current;
  while (std::getline(in, line)) {
    if (line.rfind("event: ", 0) == 0)
      current.name = line.substr(7);
    else if (line.rfind("data: ", 0) == 0)
      current.data = json::parse(line.substr(6));
    else if (line.empty() && !current.name.empty())
      events.push_back(std::exchange(current, {}));
  }
  return events;
}

std::string read_stream(const test::ServerProcess& s, const std::string& path, int& status,
                        std::string& type) {
  std::string text;
  auto res = s.client()->Get(path.c_str(), [&](const char* data, size_t n) {
    text.append(data, n);
    return true;
  });
  status = res ? res->status : 0;
  type = res ? res->get_header_value("Content-Type") : "";
  return text;
}

TEST(RenderApi, EventsStreamProgressUntilTheJobEnds) {
  auto& s = render_server();
  const std::string id = submit(s, render_body("forest", 96, 96, 64));
  int code = 0;
  std::string type;
  const auto events = parse_events(read_stream(s, "/api/v1/renders/" + id + "/events", code, type));
  EXPECT_EQ(code, 200);
  EXPECT_EQ(type, "text/event-stream");
  ASSERT_GE(events.size(), 1u);
  EXPECT_EQ(events.back().name, "end");
  EXPECT_EQ(events.back().data["status"], "done");
  EXPECT_EQ(events.back().data["spp_done"], 64);
  double last = 0;
  for (size_t i = 0; i + 1 < events.size(); ++i) {
    EXPECT_EQ(events[i].name, "progress");
    EXPECT_EQ(events[i].data["id"], id);
    EXPECT_GE(events[i].data["progress"].get<double>(), last);
    last = events[i].data["progress"];
  }
  // A finished job's stream is just the end event.
  const auto again = parse_events(read_stream(s, "/api/v1/renders/" + id + "/events", code, type));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].name, "end");
  read_stream(s, "/api/v1/renders/nope/events", code, type);
  EXPECT_EQ(code, 404);
}

// The status of GET path, read from the headers only: the connection is dropped before the body.
int probe_status(const test::ServerProcess& s, const std::string& path) {
  int status = 0;
  s.client()->Get(
      path.c_str(),
      [&](const httplib::Response& r) {
        status = r.status;
        return false;
      },
      [](const char*, size_t) { return false; });
  return status;
}

TEST(RenderApi, EventStreamsAreBoundedAndADisconnectFreesTheSlot) {
  test::ServerProcess s({"--max-event-streams", "1"});
  const std::string id = submit(s, render_body("default", 512, 512, 4096));
  CancelOnExit guard(s, id);
  const std::string path = "/api/v1/renders/" + id + "/events";

  std::atomic<bool> first_event{false}, stop{false};
  std::thread holder([&] {
    s.client()->Get(path.c_str(), [&](const char*, size_t) {
      first_event = true;
      return !stop.load();  // false: the client hangs up
    });
  });
  while (!first_event) std::this_thread::sleep_for(5ms);
  EXPECT_EQ(probe_status(s, path), 503);  // the one stream is taken
  const Reply busy = get(s, "/api/v1/renders/" + id);
  EXPECT_EQ(busy.status, 200);  // polling still works

  stop = true;
  holder.join();
  // The server notices the hang-up at its next write (within about 250 ms) and frees the slot.
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  int status = 503;
  while (status == 503 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);
    status = probe_status(s, path);
  }
  EXPECT_EQ(status, 200);
}

TEST(RenderApi, OtherRequestsAnswerWhileRendersRun) {
  auto& s = render_server();
  const std::string a = submit(s, render_body("forest", 512, 512, 4096));
  CancelOnExit guard_a(s, a);
  const std::string b = submit(s, render_body("forest", 512, 512, 4096));
  CancelOnExit guard_b(s, b);
  poll(s, a, [](const json& st) { return st["status"] == "running"; });
  poll(s, b, [](const json& st) { return st["status"] == "running"; });

  const Reply health = get(s, "/api/v1/health");
  EXPECT_EQ(health.status, 200) << health.body;
  const auto samples =
      s.client()->Post("/api/v1/envmaps/forest/samples", json{{"count", 1000}}.dump(), "application/json");
  ASSERT_TRUE(samples);
  EXPECT_EQ(samples->status, 200);
  EXPECT_EQ(get(s, "/api/v1/envmaps/forest").status, 200);
  EXPECT_EQ(get(s, "/api/v1/renders").status, 200);
  EXPECT_EQ(status(s, a)["status"], "running");  // the answers came while both renders ran
  EXPECT_EQ(status(s, b)["status"], "running");
}

TEST(RenderApi, BadFieldsAreRejectedWith400NamingTheField) {
  auto& s = render_server();
  json body = render_body("forest", 32, 32, 4);
  body["colour"] = "red";
  expect_field_error(post(s, "/api/v1/renders", body), "colour");

  body = render_body("forest", 32, 32, 4,
                     {{"objects", json::array({{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}},
                                               {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}},
                                               {{"type", "sphere"},
                                                {"center", {0, 0, 0}},
                                                {"radius", 1},
                                                {"material", {{"type", "dielectric"}, {"ior", 0.5}}}}})}});
  expect_field_error(post(s, "/api/v1/renders", body), "scene.objects[2].material.ior");
  expect_field_error(post(s, "/api/v1/renders", render_body("forest", 100000, 32, 4)), "width");
  expect_field_error(post(s, "/api/v1/renders", render_body("forest", 32, 32, 0)), "spp");
  expect_field_error(post(s, "/api/v1/renders", render_body("no-such-map", 32, 32, 4)), "envmap");
  body = render_body("forest", 32, 32, 4);
  body["lighting"] = {{"mode", "sun"}};
  expect_field_error(post(s, "/api/v1/renders", body), "lighting.mode");

  const auto bad_json = s.client()->Post("/api/v1/renders", "{\"envmap\":", "application/json");
  ASSERT_TRUE(bad_json);
  EXPECT_EQ(bad_json->status, 400);
  EXPECT_EQ(json::parse(bad_json->body)["error"]["code"], "invalid_json");
  EXPECT_EQ(get(s, "/api/v1/renders/0123456789abcdef").status, 404);
  EXPECT_EQ(get(s, "/api/v1/renders/0123456789abcdef/image").status, 404);
}

json mesh_scene(const std::string& path) {
  // bunny.obj is y-up (an OBJ's default up axis) and about 10 units tall: scaled to about 1.
  return {{"camera", {{"position", {0, -3, 0.5}}, {"look_at", {0, 0, 0.5}}, {"up", {0, 0, 1}}}},
          {"objects", json::array({{{"type", "mesh"},
                                    {"path", path},
                                    {"transform", {{"scale", 0.1}}},
                                    {"material", {{"type", "diffuse"}, {"albedo", 0.7}}}}})}};
}

TEST(RenderApi, MeshPathsMustStayInsideTheDataDir) {
  auto& s = render_server();
  const std::string id = submit(s, render_body("forest", 32, 32, 2, mesh_scene("meshes/bunny.obj")));
  const json st = wait_finished(s, id);
  EXPECT_EQ(st["status"], "done") << st.dump();

  const std::string field = "scene.objects[0].path";
  for (const std::string& bad : std::vector<std::string>{
           "../meshes/bunny.obj", "meshes/../../etc/passwd", "/etc/passwd",
           (test::mesh_path("bunny.obj")).string(), "escape.obj", "meshes/missing.obj", "meshes"})
    expect_field_error(post(s, "/api/v1/renders", render_body("forest", 32, 32, 2, mesh_scene(bad))), field);

  test::ServerProcess no_data_dir;  // without --data-dir no path is accepted
  expect_field_error(
      post(no_data_dir, "/api/v1/renders", render_body("default", 32, 32, 2, mesh_scene("meshes/bunny.obj"))),
      field);
}

TEST(RenderQueue, AFullQueueAnswers503WithRetryAfter) {
  auto& s = small_server();
  const std::string running = submit(s, render_body("default", 512, 512, 4096));
  CancelOnExit guard_running(s, running);
  const std::string queued = submit(s, render_body("default", 512, 512, 4096));
  CancelOnExit guard_queued(s, queued);

  const Reply full = post(s, "/api/v1/renders", render_body("default", 32, 32, 1));
  ASSERT_EQ(full.status, 503) << full.body;
  EXPECT_EQ(full.body_json()["error"]["code"], "queue_full");
  const int retry = std::stoi(full.header("Retry-After"));
  EXPECT_GE(retry, 1);
  EXPECT_LE(retry, 60);

  EXPECT_EQ(status(s, queued)["status"], "queued");
  const Reply no_image = get(s, "/api/v1/renders/" + queued + "/image");
  EXPECT_EQ(no_image.status, 409);
  EXPECT_EQ(no_image.body_json()["error"]["code"], "no_image_yet");

  const Reply cancel = del(s, "/api/v1/renders/" + queued);  // a queued job is cancelled at once
  ASSERT_EQ(cancel.status, 202);
  EXPECT_EQ(cancel.body_json()["status"], "cancelled");
  const std::string next = submit(s, render_body("default", 32, 32, 1));  // its slot is free again
  CancelOnExit guard_next(s, next);
  EXPECT_FALSE(next.empty());

  const Reply list = get(s, "/api/v1/renders");
  EXPECT_EQ(list.body_json()["running"], 1);
  EXPECT_EQ(list.body_json()["queued"], 1);
}

TEST(RenderQueue, AMeshOverTheTriangleLimitIsRefusedAtSubmission) {
  auto& s = small_server();  // --max-mesh-triangles 1000
  const Reply r =
      post(s, "/api/v1/renders", render_body("default", 32, 32, 1, mesh_scene("meshes/bunny.obj")));
  EXPECT_EQ(r.status, 400) << r.body;
  EXPECT_NE(r.body.find("scene.objects[0].path"), std::string::npos) << r.body;
  EXPECT_NE(r.body.find("has over 1000 triangles"), std::string::npos) << r.body;
}

TEST(RenderQueue, FinishedJobsAreBoundedAndTheOldestDropped) {
  auto& s = small_server();  // --max-finished-jobs 2
  std::vector<std::string> ids;
  for (int i = 0; i < 3; ++i) {
    ids.push_back(submit(s, render_body("default", 16, 16, 1)));
    EXPECT_EQ(wait_finished(s, ids.back())["status"], "done");
  }
  // A job says done as its work ends; its runner retires it (and drops the oldest) just after.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (get(s, "/api/v1/renders/" + ids[0]).status != 404 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(get(s, "/api/v1/renders/" + ids[0]).status, 404);
  std::vector<std::string> listed;
  const json all = get(s, "/api/v1/renders").body_json();
  for (const auto& j : all["renders"]) listed.push_back(j["id"]);
  EXPECT_EQ(listed, (std::vector<std::string>{ids[1], ids[2]}));
}

// --max-finished-mb: a finished 256x256 render keeps 12 B/px (768 KiB), so a second one passes 1 MiB and
// the oldest is dropped.
TEST(RenderQueue, FinishedJobsAreBoundedInBytes) {
  test::ServerProcess s({"--max-finished-mb", "1"});
  const std::string first = submit(s, render_body("default", 256, 256, 1));
  EXPECT_EQ(wait_finished(s, first)["status"], "done");
  const std::string second = submit(s, render_body("default", 256, 256, 1));
  EXPECT_EQ(wait_finished(s, second)["status"], "done");
  EXPECT_EQ(get(s, "/api/v1/renders/" + first).status, 404);
  EXPECT_EQ(get(s, "/api/v1/renders/" + second + "/image?format=exr").status, 200);
}

TEST(RenderShutdown, SigtermInterruptsARunningRenderAndTheServerExits) {
  std::string log_path, id;
  {
    test::ServerProcess s({"--shutdown-grace-s", "1"});
    log_path = s.log_path();
    id = submit(s, render_body("default", 512, 512, 4096));
    poll(s, id, [](const json& st) { return st["status"] == "running"; });
  }  // SIGTERM; the destructor waits up to 5 s before it would SIGKILL
  std::ifstream in(log_path);
  const std::string log{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(log.find("render " + id + " interrupted"), std::string::npos) << log;
  EXPECT_NE(log.find("stopped"), std::string::npos) << log;
}

}  // namespace
}  // namespace lp

// What the state directory keeps, on the real server: a write that fails (a full disk) fails its request
// with 507 and keeps nothing, a render whose image cannot be kept fails saying so, names the server's own
// temporary files look like survive a restart, start-up removes files no record names and drops records
// whose files are gone, an asset's files never take another asset's record name, no message names a
// server path, and renders racing deletes of their asset get 4xx.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/small_disk.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;
using namespace std::chrono_literals;

// A PFM file of 8x4 pixels of one grey.
std::string pfm_map() {
  std::string out = "PF\n8 4\n-1.0\n";
  const float v = 0.5f;
  for (int i = 0; i < 8 * 4 * 3; ++i) out.append(reinterpret_cast<const char*>(&v), sizeof v);
  return out;
}

const std::string kGlb = [] {
  const auto bytes = test::read_bytes(test::model_path("quad.glb"));
  return std::string(bytes.begin(), bytes.end());
}();

// A server keeping its state in `dir` (seen by the test at `seen`), started under `launcher`.
class StateServer {
 public:
  StateServer(fs::path dir, fs::path seen, std::vector<std::string> launcher = {})
      : dir_(std::move(dir)), seen_(std::move(seen)), launcher_(std::move(launcher)) {
    start();
  }
  void start() {
    server_ = std::make_unique<test::ServerProcess>(std::vector<std::string>{"--state-dir", dir_.string()},
                                                    test::Variables{}, test::StartUntil::Ready, launcher_);
    client_ = server_->client();
  }
  void restart() {
    client_.reset();
    server_.reset();
    start();
  }
  Reply upload_map(const std::string& name) const {
    return test::reply(
        client_->Post(("/api/v1/envmaps?name=" + name).c_str(), pfm_map(), "application/octet-stream"));
  }
  Reply upload_asset(const std::string& name) const {
    return test::reply(
        client_->Post(("/api/v1/assets?name=" + name).c_str(), kGlb, "application/octet-stream"));
  }
  // Requests from a connection of their own, for another thread.
  struct Client {
    explicit Client(const StateServer& server) : client(server.process().client()) {}
    Reply render(const std::string& envmap, int size, const std::string& mesh) const {
      return test::reply(
          client->Post("/api/v1/renders", render_body(envmap, size, mesh).dump(), "application/json"));
    }
    std::unique_ptr<httplib::Client> client;
  };
  static json render_body(const std::string& envmap, int size, const std::string& mesh) {
    json body = {{"envmap", envmap}, {"width", size}, {"height", size}, {"spp", 1}};
    if (!mesh.empty()) {
      const json object = {{"type", "mesh"}, {"path", mesh}};
      body["scene"] = {{"objects", {object}}, {"camera", {{"position", {0, -4, 1}}, {"look_at", {0, 0, 0}}}}};
    }
    return body;
  }
  Reply render(const std::string& envmap, int size, const std::string& mesh = "") const {
    return test::reply(
        client_->Post("/api/v1/renders", render_body(envmap, size, mesh).dump(), "application/json"));
  }
  Reply get(const std::string& path) const { return test::reply(client_->Get(path.c_str())); }
  Reply del(const std::string& path) const { return test::reply(client_->Delete(path.c_str())); }
  std::set<std::string> listed(const std::string& kind, const std::string& key) const {
    const json list = get("/api/v1/" + kind).body_json();
    std::set<std::string> out;
    for (const auto& e : list[kind]) out.insert(e[key].get<std::string>());
    return out;
  }
  json finished_render(const std::string& id) const { return test::finished_render(*client_, id); }
  std::set<std::string> files_in(const std::string& folder) const {
    std::set<std::string> out;
    for (const auto& entry : fs::directory_iterator(seen_ / folder))
      out.insert(entry.path().filename().string());
    return out;
  }
  const fs::path& seen() const { return seen_; }
  const test::ServerProcess& process() const { return *server_; }
  httplib::Client& client() const { return *client_; }

 private:
  fs::path dir_, seen_;
  std::vector<std::string> launcher_;
  std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<httplib::Client> client_;
};

// A refusal of the server's storage: 507 insufficient_storage naming the resource, no server path.
void expect_storage_full(const Reply& r, const std::string& resource, const fs::path& state_dir) {
  EXPECT_EQ(r.status, 507) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "insufficient_storage") << r.body;
  EXPECT_NE(r.body.find(resource), std::string::npos) << r.body;
  EXPECT_EQ(r.body.find(state_dir.string()), std::string::npos) << r.body;
}

TEST(StateDurability, AFullDiskFailsUploadsWith507AndKeepsNothing) {
  test::SmallDisk disk(4 << 20);
  const fs::path state = disk.path() / "state";
  StateServer s(state, disk.outside() / "state", disk.launcher());
  ASSERT_EQ(s.upload_map("kept").status, 201);
  ASSERT_EQ(s.upload_asset("box").status, 201);

  disk.fill();
  for (const std::string name : {"sky1", "sky2", "sky3"})
    expect_storage_full(s.upload_map(name), name, state);
  expect_storage_full(s.upload_asset("car"), "car", state);
  expect_storage_full(s.render("kept", 8), "render", state);
  EXPECT_EQ(s.get("/api/v1/renders").body_json()["renders"].size(), 0u);
  EXPECT_EQ(s.listed("envmaps", "name"), (std::set<std::string>{"default", "kept"}));
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"box"}));

  disk.free();
  s.restart();
  EXPECT_EQ(s.listed("envmaps", "name"), (std::set<std::string>{"default", "kept"}));
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"box"}));
  EXPECT_EQ(s.files_in("maps"), (std::set<std::string>{"kept.json", "kept.pfm"}));
  EXPECT_EQ(s.files_in("assets"), (std::set<std::string>{"box.json"}));
  EXPECT_EQ(s.files_in("asset-files"), (std::set<std::string>{"box"}));
  EXPECT_TRUE(s.files_in("renders").empty());
  EXPECT_EQ(s.upload_map("sky1").status, 201);
}

TEST(StateDurability, ARenderWhoseImageCannotBeKeptFailsSayingSo) {
  test::SmallDisk disk(4 << 20);
  const fs::path state = disk.path() / "state";
  StateServer s(state, disk.outside() / "state", disk.launcher());
  disk.fill(3 * 4096);  // room for the render's record, not for its image (64x64 pixels, over 24 KB)
  const Reply r = s.render("default", 64);
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string id = r.body_json()["id"];
  const json st = s.finished_render(id);
  EXPECT_EQ(st["status"], "failed") << st.dump();
  EXPECT_EQ(st["error"]["code"], "insufficient_storage") << st.dump();
  EXPECT_EQ(st.dump().find(state.string()), std::string::npos) << st.dump();

  disk.free();
  s.restart();
  const Reply after = s.get("/api/v1/renders/" + id);
  if (after.status == 200) {
    EXPECT_NE(after.body_json()["status"], "done") << after.body;
  }
  for (const auto& file : s.files_in("renders")) EXPECT_EQ(file.find(".exr"), std::string::npos) << file;
}

TEST(StateDurability, NamesLikeTemporaryFilesSurviveARestart) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  ASSERT_EQ(s.upload_asset("car.tmp-v2").status, 201);
  ASSERT_EQ(s.upload_map("sky.tmp-2").status, 201);
  s.restart();
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"car.tmp-v2"}));
  EXPECT_EQ(s.listed("envmaps", "name"), (std::set<std::string>{"default", "sky.tmp-2"}));
  EXPECT_EQ(s.render("sky.tmp-2", 8, "assets/car.tmp-v2").status, 202);
}

TEST(StateDurability, StartReconcilesFilesAndRecordsBothWays) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  ASSERT_EQ(s.upload_map("sky").status, 201);
  ASSERT_EQ(s.upload_map("lost").status, 201);
  ASSERT_EQ(s.upload_asset("box").status, 201);
  ASSERT_EQ(s.upload_asset("gone").status, 201);
  const Reply r = s.render("sky", 8);
  ASSERT_EQ(r.status, 202);
  const std::string id = r.body_json()["id"];
  ASSERT_EQ(s.finished_render(id)["status"], "done");
  s.restart();  // nothing of the first run in flight
  const std::set<std::string> renders = s.files_in("renders");

  // What a crash can leave: files whose record it lost, records whose files it lost.
  const std::string stray_image = "0123456789abcdef.4.exr";
  std::ofstream(dir.path() / "renders" / stray_image) << "image";
  std::ofstream(dir.path() / "maps" / "orphan.pfm") << pfm_map();
  fs::create_directories(dir.path() / "asset-files" / "ghost" / "sub");
  fs::remove(dir.path() / "maps" / "lost.pfm");
  fs::remove_all(dir.path() / "asset-files" / "gone");
  s.restart();

  EXPECT_EQ(s.listed("envmaps", "name"), (std::set<std::string>{"default", "sky"}));
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"box"}));
  EXPECT_EQ(s.files_in("maps"), (std::set<std::string>{"sky.json", "sky.pfm"}));
  EXPECT_EQ(s.files_in("assets"), (std::set<std::string>{"box.json"}));
  EXPECT_EQ(s.files_in("asset-files"), (std::set<std::string>{"box"}));
  EXPECT_EQ(s.files_in("renders"), renders);
  EXPECT_EQ(s.get("/api/v1/renders/" + id).body_json()["status"], "done");
  const std::string log = s.process().log();
  for (const std::string& line : std::vector<std::string>{
           "removing renders/" + stray_image + " (no record names it)",
           "removing maps/orphan.pfm (no record names it)", "removing asset-files/ghost (no record names it)",
           "dropping maps/lost.json: the map's file is missing",
           "dropping assets/gone.json: the asset's files are missing"})
    EXPECT_NE(log.find(line), std::string::npos) << line << "\n" << log;
}

TEST(StateDurability, AFinishedRenderWhoseImageIsGoneIsDropped) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  const Reply r = s.render("default", 8);
  ASSERT_EQ(r.status, 202);
  const std::string id = r.body_json()["id"];
  ASSERT_EQ(s.finished_render(id)["status"], "done");
  s.restart();
  for (const auto& file : s.files_in("renders"))
    if (file.ends_with(".exr")) fs::remove(dir.path() / "renders" / file);
  s.restart();
  EXPECT_EQ(s.get("/api/v1/renders/" + id).status, 404);
  EXPECT_TRUE(s.files_in("renders").empty());
  EXPECT_NE(s.process().log().find("dropping renders/" + id + ".json: its image is missing"),
            std::string::npos)
      << s.process().log();
}

TEST(StateDurability, AnAssetsFilesNeverTakeAnotherAssetsRecordName) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  for (const std::string name : {"b", "b.json", "c.json", "c"}) {
    const Reply r = s.upload_asset(name);
    EXPECT_EQ(r.status, 201) << name << ": " << r.body;
    EXPECT_EQ(r.body.find(dir.path().string()), std::string::npos) << r.body;
  }
  s.restart();
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"b", "b.json", "c", "c.json"}));
  for (const std::string name : {"b", "b.json"})
    EXPECT_EQ(s.render("default", 8, "assets/" + name).status, 202);
}

// State directories written before asset-files/ kept an asset's folder beside its record.
TEST(StateDurability, AssetFoldersOfTheEarlierLayoutAreMoved) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  ASSERT_EQ(s.upload_asset("box").status, 201);
  s.restart();
  fs::rename(dir.path() / "asset-files" / "box", dir.path() / "assets" / "box");
  s.restart();
  EXPECT_EQ(s.listed("assets", "name"), (std::set<std::string>{"box"}));
  EXPECT_EQ(s.files_in("assets"), (std::set<std::string>{"box.json"}));
  EXPECT_EQ(s.files_in("asset-files"), (std::set<std::string>{"box"}));
  EXPECT_EQ(s.render("default", 8, "assets/box").status, 202);
}

// Renders name an asset that another client deletes and uploads again, for a few seconds: each render is
// accepted or refused for the asset (4xx), never with a server error, and none accepted fails.
TEST(StateDurability, RendersRacingDeletesOfTheirAssetGetNoServerError) {
  test::TempDir dir;
  StateServer s(dir.path(), dir.path());
  std::atomic<bool> stop{false};
  std::thread churn([&] {
    auto c = s.process().client();
    while (!stop) {
      c->Post("/api/v1/assets?name=racer", kGlb, "application/octet-stream");
      std::this_thread::sleep_for(5ms);
      c->Delete("/api/v1/assets/racer");
    }
  });
  std::mutex mutex;
  std::map<int, int> statuses;
  std::vector<std::string> server_errors, accepted;
  const auto end = std::chrono::steady_clock::now() + 4s;
  const auto post_renders = [&] {
    StateServer::Client c(s);
    while (std::chrono::steady_clock::now() < end) {
      const Reply r = c.render("default", 4, "assets/racer");
      std::lock_guard lock(mutex);
      ++statuses[r.status];
      if (r.status >= 500 && r.status != 503) server_errors.push_back(r.body);
      if (r.status == 202) accepted.push_back(r.body_json()["id"]);
    }
  };
  std::thread other(post_renders);
  post_renders();
  other.join();
  stop = true;
  churn.join();
  std::string counts;
  for (const auto& [status, n] : statuses) counts += std::to_string(status) + ": " + std::to_string(n) + "  ";
  std::cout << "render statuses: " << counts << "\n";
  EXPECT_TRUE(server_errors.empty()) << server_errors.size()
                                     << " server errors, the first: " << server_errors[0];
  EXPECT_GT(statuses[202], 0) << counts;
  EXPECT_EQ(statuses[0], 0) << counts;
  for (const auto& id : accepted) {
    const json st = s.finished_render(id);
    EXPECT_NE(st["status"], "failed") << st.dump();
  }
}

}  // namespace
}  // namespace lp

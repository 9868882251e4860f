// --max-memory-mb against the real server: maps fill the budget (derived tables are evicted first,
// then loads are refused with 507), deleting a map returns its bytes, decodes reserve the pixels a
// header claims before allocating them (503 with Retry-After while work in flight holds the memory),
// and pictures larger than the budget are refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/render/textured_preset.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

constexpr int64_t kMiB = int64_t{1} << 20;

// A little-endian RGB PFM of `width` x `height` with every value `v`.
std::string pfm(int width, int height, float v) {
  std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  for (int64_t i = 0; i < int64_t(width) * height * 3; ++i) out.append(reinterpret_cast<const char*>(&v), 4);
  return out;
}

Reply upload(const test::ServerProcess& s, const std::string& name, const std::string& bytes) {
  return test::reply(
      s.client()->Post(("/api/v1/envmaps?name=" + name).c_str(), bytes, "image/x-portable-floatmap"));
}

Reply get(const test::ServerProcess& s, const std::string& path) {
  return test::reply(s.client()->Get(path.c_str()));
}

Reply post_json(const test::ServerProcess& s, const std::string& path, const json& body) {
  return test::reply(s.client()->Post(path.c_str(), body.dump(), "application/json"));
}

// The reply of `request`, asked again while it is 503 (the table of the previous request is released
// when its stream has been written, which may come just after the client has read it).
template <class F>
Reply retrying_503(F request) {
  Reply r;
  for (int attempt = 0; attempt < 600; ++attempt) {
    r = request();
    if (r.status != 503) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return r;
}

// A PFM header claiming `width` x `height` float RGB pixels, followed by one pixel.
std::string claim(int width, int height) {
  std::string out = "PF\n";
  out += std::to_string(width);
  out += ' ';
  out += std::to_string(height);
  out += "\n-1.0\n";
  out.resize(out.size() + 12, '\0');
  return out;
}

void expect_refusal(const Reply& r, int status, const std::string& code) {
  EXPECT_EQ(r.status, status) << r.body;
  if (r.status != status) return;
  EXPECT_EQ(r.body_json()["error"]["code"], code);
  EXPECT_NE(r.body_json()["error"]["message"].get<std::string>().find("--max-memory-mb"), std::string::npos);
  if (status == 503) {
    EXPECT_EQ(r.header("Retry-After"), "2");
  }
}

TEST(MemoryBudgetApi, MapsFillTheBudgetCachesGoFirstThenLoadsAre507AndADeleteMakesRoom) {
  test::ServerProcess s({"--max-memory-mb", "40"});
  const std::string map = pfm(512, 256, 0.5f);
  const int64_t image_bytes = 512 * 256 * 12;
  std::vector<std::string> loaded;
  Reply refused;
  for (int i = 0; i < 40 && refused.status == 0; ++i) {
    const std::string name = fmt::format("m{}", i);
    const Reply r = upload(s, name, map);
    if (r.status != 201) {
      refused = r;
      break;
    }
    loaded.push_back(name);
    // A map is loaded with its sampling table: 9 bytes per pixel (the inverse CDFs with their guide
    // tables) and a few per row; the alias table is made when independent samples are first drawn.
    const auto bytes = r.body_json()["memory_bytes"].get<int64_t>();
    EXPECT_GE(bytes, image_bytes + 512 * 256 * 9) << name;
    EXPECT_LT(bytes, image_bytes + 512 * 256 * 10) << name;
  }
  ASSERT_GE(loaded.size(), 3u);
  expect_refusal(refused, 507, "insufficient_memory");
  // ... and the tables of the first maps were evicted to load the later ones.
  EXPECT_EQ(get(s, "/api/v1/envmaps/m0").body_json()["memory_bytes"], image_bytes);

  // Still up, and every map it holds is served.
  for (const auto& name : loaded) {
    EXPECT_EQ(get(s, "/api/v1/envmaps/" + name).status, 200) << name;
    const Reply image = retrying_503([&] { return get(s, "/api/v1/envmaps/" + name + "/image?format=pfm"); });
    EXPECT_EQ(image.status, 200) << name << ": " << image.body.substr(0, 300);
    EXPECT_EQ(image.body, map) << name;
  }

  // Deleting one map gives its bytes back: the refused load now fits, and every map can be sampled
  // (building its table again evicts another's).
  ASSERT_EQ(s.client()->Delete("/api/v1/envmaps/m1")->status, 204);
  EXPECT_EQ(upload(s, "after_delete", map).status, 201);
  loaded.erase(loaded.begin() + 1);
  for (const auto& name : loaded) {
    const Reply r = retrying_503([&] {
      return post_json(s, "/api/v1/envmaps/" + name + "/samples", {{"count", 16}});
    });
    EXPECT_EQ(r.status, 200) << name << ": " << r.body.substr(0, 300);
  }
  // Independent samples were drawn through the alias table: 8 bytes more per pixel.
  const auto sampled = get(s, "/api/v1/envmaps/" + loaded.back()).body_json()["memory_bytes"].get<int64_t>();
  EXPECT_GE(sampled, image_bytes + 512 * 256 * 17);
  EXPECT_LT(sampled, image_bytes + 512 * 256 * 18);
  EXPECT_TRUE(s.alive());
}

TEST(MemoryBudgetApi, HugeClaimsWhileARenderHoldsMemoryGet503ThenFitOnceItEnds) {
  test::ServerProcess s({"--max-memory-mb", "96", "--max-render-spp", "1000000"});
  // 768 x 768 holds about 50 MiB while it runs (film, images, checkpoint).
  const Reply render = post_json(s, "/api/v1/renders",
                                 {{"envmap", "default"},
                                  {"scene", {{"preset", "sphere"}}},
                                  {"width", 768},
                                  {"height", 768},
                                  {"spp", 1000000}});
  ASSERT_EQ(render.status, 202) << render.body;
  const std::string id = render.body_json()["id"];

  // Each claims 4096 x 1024 float RGB (48 MiB) in a file of a few bytes.
  const std::string big = claim(4096, 1024);
  std::vector<std::future<Reply>> uploads;
  for (int i = 0; i < 8; ++i)
    uploads.push_back(
        std::async(std::launch::async, [&, i] { return upload(s, "claim" + std::to_string(i), big); }));
  for (auto& u : uploads) expect_refusal(u.get(), 503, "memory_busy");

  // A claim larger than the whole budget can never fit.
  expect_refusal(upload(s, "huge", claim(8192, 4096)), 507, "insufficient_memory");

  // Once the render ends, the claim gets as far as the decoder, which finds the data missing.
  ASSERT_EQ(s.client()->Delete(("/api/v1/renders/" + id).c_str())->status, 202);
  const Reply after = retrying_503([&] { return upload(s, "claim", big); });
  EXPECT_EQ(after.status, 422) << after.body;
  EXPECT_TRUE(s.alive());
}

TEST(MemoryBudgetApi, SamplePicturesOverTheBudgetAreRefused) {
  test::ServerProcess s({"--max-memory-mb", "64", "--max-samples", "10000000"});
  const Reply small = get(s, "/api/v1/envmaps/default/samples.png?count=1000");
  EXPECT_EQ(small.status, 200) << small.body.substr(0, 300);
  EXPECT_EQ(small.type(), "image/png");
  // 10 million samples take about 450 MiB before the picture is drawn.
  expect_refusal(get(s, "/api/v1/envmaps/default/samples.png?count=10000000"), 507, "insufficient_memory");
  EXPECT_EQ(get(s, "/api/v1/envmaps/default/samples.png?count=1000").status, 200);
}

int64_t used_bytes(const test::ServerProcess& s) {
  const Reply health = get(s, "/api/v1/health");
  EXPECT_EQ(health.status, 200);
  return health.status == 200 ? health.body_json()["memory"]["used_bytes"].get<int64_t>() : -1;
}

json tiny_render(const json& scene) {
  return {{"envmap", "default"}, {"scene", scene}, {"width", 16}, {"height", 16}, {"spp", 1}};
}

TEST(MemoryBudgetApi, RenderMeshesAreReservedFromTheirTriangleCount) {
  test::TempDir data;
  std::ofstream(data.path() / "small.obj") << test::grid_obj(20);   // 800 triangles
  std::ofstream(data.path() / "large.obj") << test::grid_obj(300);  // 180,000 triangles: about 44 MiB
  test::ServerProcess s({"--max-memory-mb", "40", "--data-dir", data.path().string()});
  const auto mesh_scene = [](const std::string& file) {
    return json{{"objects", json::array({{{"type", "mesh"}, {"path", file}}})}};
  };
  expect_refusal(post_json(s, "/api/v1/renders", tiny_render(mesh_scene("large.obj"))), 507,
                 "insufficient_memory");
  const Reply small = post_json(s, "/api/v1/renders", tiny_render(mesh_scene("small.obj")));
  EXPECT_EQ(small.status, 202) << small.body;
}

// Bytes held for good (maps, the presets' models, finished renders' images): used minus evictable caches.
int64_t held_bytes(const test::ServerProcess& s) {
  const Reply health = get(s, "/api/v1/health");
  EXPECT_EQ(health.status, 200);
  const json memory = health.body_json()["memory"];
  return memory["used_bytes"].get<int64_t>() - memory["cache_bytes"].get<int64_t>();
}

int64_t finished_render_bytes(const test::ServerProcess& s, const json& body) {
  const Reply r = post_json(s, "/api/v1/renders", body);
  EXPECT_EQ(r.status, 202) << r.body;
  if (r.status != 202) return 0;
  EXPECT_EQ(test::finished_render(*s.client(), r.body_json()["id"])["status"], "done");
  return held_bytes(s);
}

// The textured preset's model (geometry and textures) is counted in the budget when a render first uses
// it, once: later renders of the preset add only their images. (A budget without room for it refuses it
// naming it: tests/unit/model_cache_test.cpp.)
TEST(MemoryBudgetApi, TheTexturedPresetsModelIsHeldInTheBudgetOnce) {
  const json textured = tiny_render({{"preset", "textured"}});
  const int64_t image = EnvMap::image_bytes(16, 16);
  test::ServerProcess s;
  const int64_t start = held_bytes(s);  // the default map
  const int64_t first = finished_render_bytes(s, textured);
  EXPECT_EQ(first - start, render::textured_preset_model()->memory_bytes() + image);
  EXPECT_EQ(finished_render_bytes(s, textured) - first, image);
}

TEST(MemoryBudgetApi, FinishedRendersRestoredAtStartHoldTheirImages) {
  test::TempDir state;
  const std::vector<std::string> flags = {"--state-dir", state.path().string()};
  {
    test::ServerProcess first(flags);
    json body = tiny_render({{"preset", "sphere"}});
    body["width"] = 256;
    body["height"] = 128;
    const Reply r = post_json(first, "/api/v1/renders", body);
    ASSERT_EQ(r.status, 202) << r.body;
    const std::string id = r.body_json()["id"];
    for (int i = 0; i < 3000 && get(first, "/api/v1/renders/" + id).body_json()["status"] != "done"; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(get(first, "/api/v1/renders/" + id).body_json()["status"], "done");
  }
  test::ServerProcess restored(flags);
  test::ServerProcess fresh;
  ASSERT_EQ(get(restored, "/api/v1/renders").body_json()["renders"].size(), 1u);
  // The only difference between the two servers is the restored 256 x 128 float RGB image.
  EXPECT_EQ(used_bytes(restored) - used_bytes(fresh), int64_t{256} * 128 * 3 * 4);
}

}  // namespace
}  // namespace lp

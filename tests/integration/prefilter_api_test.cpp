// Prefiltered specular chains on the real server: a job from POST to done with its progress, the files
// read back (KTX2, a KTX2 cube map, EXR in every projection) against analytic values, a long job
// cancelled while it runs, a file asked of a job still queued, a chain reused for the same map content
// and parameters (and not after a cancel or a removal), a bake target's files, and bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <tuple>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ktx2.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/shared_client.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

using test::shared_client;
using test::shared_get;

Reply submit(const std::string& map, const std::string& body) {
  return test::reply(
      shared_client().Post(("/api/v1/envmaps/" + map + "/prefilter").c_str(), body, "application/json"));
}

Reply del(const std::string& path) {
  return test::reply(shared_client().Delete(path.c_str()));
}

const std::string& white() {
  static const std::string name = [] {
    const Reply r = test::upload_white_map(shared_client(), "prefilter_white");
    EXPECT_TRUE(r.status == 201 || r.status == 409) << r.body;
    return std::string("prefilter_white");
  }();
  return name;
}

// Submits and waits for the end; the final status.
json finished(const std::string& map, const std::string& body) {
  const Reply r = submit(map, body);
  EXPECT_EQ(r.status, 202) << r.body;
  const json queued = r.body_json();
  EXPECT_EQ(r.header("Location"), "/api/v1/prefilters/" + queued["id"].get<std::string>());
  return test::finished_job(shared_client(), r.header("Location"));
}

std::vector<uint8_t> bytes_of(const Reply& r) {
  return {r.body.begin(), r.body.end()};
}

void expect_all_near(const Image& image, float value, float tolerance) {
  for (const float v : image.data()) ASSERT_NEAR(v, value, tolerance);
}

TEST(PrefilterApi, AWhiteMapIsOneAtEveryLevelOfTheKtx2File) {
  const json st = finished(white(), R"({"levels":5,"base_size":64,"samples":256})");
  ASSERT_EQ(st["status"], "done") << st;
  EXPECT_EQ(st["progress"], 1.0);
  EXPECT_EQ(st["files_available"], true);
  EXPECT_EQ(st["format"], "ktx2");
  EXPECT_EQ(st["precision"], "half");
  ASSERT_EQ(st["files"].size(), 1u);
  const Reply file = shared_get(st["files"][0]["url"]);
  ASSERT_EQ(file.status, 200) << file.body;
  EXPECT_EQ(file.type(), "image/ktx2");
  const Ktx2Texture t = read_ktx2(bytes_of(file), {});
  EXPECT_EQ(t.vk_format, 97u);
  ASSERT_EQ(t.levels.size(), 5u);
  for (size_t i = 0; i < t.levels.size(); ++i) {
    EXPECT_EQ(t.levels[i].width(), 64 >> i);
    EXPECT_EQ(t.levels[i].height(), 32 >> i);
    expect_all_near(t.levels[i], 1.0f, 1e-3f);
  }
  EXPECT_EQ(t.metadata.at("KTXorientation"), "rd");
  EXPECT_EQ(t.metadata.at("lightprobe.roughness"), st["convention"]["roughness"]);
}

TEST(PrefilterApi, ACubeIsAKtx2CubeMapOfSixFacesAtEveryLevel) {
  const json st = finished(white(), R"({"levels":4,"base_size":32,"samples":64,"projection":"cube"})");
  ASSERT_EQ(st["status"], "done") << st;
  EXPECT_EQ(st["projection"], "cube");
  EXPECT_EQ(st["level_info"][1]["size"], 16);
  EXPECT_EQ(st["level_info"][1]["width"], 6 * 16);
  EXPECT_EQ(st["level_info"][1]["height"], 16);
  const std::string faces = st["convention"]["cube_faces"];
  EXPECT_NE(faces.find("+X, -X, +Y, -Y, +Z, -Z"), std::string::npos) << faces;
  const Reply file = shared_get(st["files"][0]["url"]);
  ASSERT_EQ(file.status, 200) << file.body;
  EXPECT_EQ(file.type(), "image/ktx2");
  const Ktx2Texture t = read_ktx2(bytes_of(file), {});
  EXPECT_EQ(t.faces, 6u);
  ASSERT_EQ(t.levels.size(), 4u);
  for (size_t i = 0; i < t.levels.size(); ++i) {
    EXPECT_EQ(t.levels[i].width(), 32 >> i);
    EXPECT_EQ(t.levels[i].height(), 6 * (32 >> i));
    expect_all_near(t.levels[i], 1.0f, 1e-3f);
  }
  EXPECT_EQ(t.metadata.at("lightprobe.cube_faces"), faces);
  EXPECT_EQ(t.metadata.at("lightprobe.projection"), st["convention"]["projection"]);
}

// One EXR a level, of the projection's shape: a white map is 1 on every texel that looks somewhere (a
// cross's six empty cells are 0). Float precision: 1 to float rounding.
TEST(PrefilterApi, EveryProjectionHasItsShapeAndIsOneForAWhiteMap) {
  const std::vector<std::tuple<std::string, int, int>> shapes = {{"latlong", 16, 8},
                                                                 {"cube", 6 * 16, 16},
                                                                 {"cross", 4 * 16, 3 * 16},
                                                                 {"octahedral", 16, 16},
                                                                 {"equal-area", 16, 16}};
  for (const auto& [projection, width, height] : shapes) {
    SCOPED_TRACE(projection);
    const json st =
        finished(white(), R"({"levels":3,"base_size":16,"samples":32,"format":"exr","precision":"float",
                                           "projection":")" +
                              projection + "\"}");
    ASSERT_EQ(st["status"], "done") << st;
    ASSERT_EQ(st["files"].size(), 3u);
    for (int level = 0; level < 3; ++level) {
      const Reply r = shared_get(st["files"][size_t(level)]["url"]);
      ASSERT_EQ(r.status, 200);
      const Image image = read_exr(bytes_of(r), {});
      ASSERT_EQ(image.width(), width >> level);
      ASSERT_EQ(image.height(), height >> level);
      float lo = 1, hi = 0;
      for (const float v : image.data()) lo = std::min(lo, v), hi = std::max(hi, v);
      EXPECT_NEAR(hi, 1.0f, 1e-4f);
      EXPECT_NEAR(lo, projection == "cross" ? 0.0f : 1.0f, 1e-4f);
    }
  }
}

TEST(PrefilterApi, ExrLevelsOfARealMapKeepItsPowerAtLevelZero) {
  const json st = finished("forest_exr", R"({"levels":4,"base_size":128,"samples":64,"format":"exr",
                                              "precision":"float"})");
  ASSERT_EQ(st["status"], "done") << st;
  ASSERT_EQ(st["files"].size(), 4u);
  EXPECT_EQ(st["files"][3]["name"], "level3.exr");
  EXPECT_EQ(st["level_info"][3]["roughness"], 1.0);
  const Reply level0 = shared_get(st["files"][0]["url"]);
  ASSERT_EQ(level0.status, 200);
  EXPECT_EQ(level0.type(), "image/x-exr");
  const Image image = read_exr(bytes_of(level0), {});
  ASSERT_EQ(image.width(), 128);
  ASSERT_EQ(image.height(), 64);
  const json power = shared_get("/api/v1/envmaps/forest_exr").body_json()["power"];
  const Rgb level_power = EnvMap::power_of(image);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(level_power[c] / power[c].get<double>(), 1.0, 1e-5);
  const Image level3 = read_exr(bytes_of(shared_get(st["files"][3]["url"])), {});
  EXPECT_EQ(level3.width(), 16);
  EXPECT_EQ(shared_get(st["files"][0]["url"].get<std::string>()).header("ETag"), level0.header("ETag"));
}

TEST(PrefilterApi, ALongJobShowsProgressAndIsCancelledWhileRunning) {
  const Reply long_job = submit("forest_exr", R"({"levels":11,"base_size":2048,"samples":1024})");
  ASSERT_EQ(long_job.status, 202) << long_job.body;
  const std::string url = long_job.header("Location");
  // A second job waits behind it: its files are not there yet.
  const Reply queued = submit(white(), "");
  ASSERT_EQ(queued.status, 202) << queued.body;
  const std::string queued_url = queued.header("Location");
  const Reply early = shared_get(queued_url + "/files/prefiltered.ktx2");
  EXPECT_EQ(early.status, 409);
  EXPECT_EQ(early.body_json()["error"]["code"], "no_image_yet");

  json st;
  for (int i = 0; i < 6000; ++i) {  // until a row of level 1 has reported
    st = shared_get(url).body_json();
    if (st["progress"].get<double>() > 0.001) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(st["status"], "running") << st;
  EXPECT_LT(st["progress"].get<double>(), 0.5);
  const Reply cancel = del(url);
  EXPECT_EQ(cancel.status, 202);
  EXPECT_EQ(cancel.body_json()["cancel_requested"], true);
  EXPECT_EQ(test::finished_job(shared_client(), url)["status"], "cancelled");
  EXPECT_EQ(shared_get(url + "/files/prefiltered.ktx2").status, 409);
  EXPECT_EQ(del(url).status, 204);
  EXPECT_EQ(shared_get(url).status, 404);

  EXPECT_EQ(test::finished_job(shared_client(), queued_url)["status"], "done");
  EXPECT_EQ(shared_get(queued_url + "/files/prefiltered.ktx2").status, 200);
  const json list = shared_get("/api/v1/prefilters").body_json();
  bool listed = false;
  for (const json& job : list["prefilters"])
    listed = listed || queued_url.ends_with(job["id"].get<std::string>());
  EXPECT_TRUE(listed);
}

// Number of jobs the server holds.
size_t job_count() {
  return shared_get("/api/v1/prefilters").body_json()["prefilters"].size();
}

TEST(PrefilterApi, TheSameChainOfTheSameMapContentIsReusedNotMadeAgain) {
  const std::string body = R"({"levels":3,"base_size":16,"samples":48,"projection":"octahedral"})";
  const Reply first = submit(white(), body);
  ASSERT_EQ(first.status, 202) << first.body;
  EXPECT_EQ(first.body_json()["reused"], false);
  const std::string url = first.header("Location");
  const json done = test::finished_job(shared_client(), url);
  ASSERT_EQ(done["status"], "done");

  // The same pixels under another id, the same parameters given explicitly: the same job, done.
  const Reply again_upload = test::upload_white_map(shared_client(), "prefilter_white_again");
  ASSERT_TRUE(again_upload.status == 201 || again_upload.status == 409);
  const size_t jobs = job_count();
  const Reply again = submit("prefilter_white_again", R"({"levels":3,"base_size":16,"samples":48,
      "projection":"octahedral","format":"ktx2","precision":"half"})");
  EXPECT_EQ(again.status, 200) << again.body;
  EXPECT_EQ(again.header("Location"), url);
  EXPECT_EQ(again.body_json()["reused"], true);
  EXPECT_EQ(again.body_json()["id"], first.body_json()["id"]);
  EXPECT_EQ(again.body_json()["status"], "done");
  EXPECT_EQ(again.body_json()["elapsed_s"], done["elapsed_s"]);  // not run again
  EXPECT_EQ(job_count(), jobs);
  EXPECT_FALSE(shared_get(url).body_json().contains("reused"));  // the answer of the POST alone says it

  // Any parameter other, or another map: a new job.
  const std::vector<std::string> others = {
      R"({"levels":2,"base_size":16,"samples":48,"projection":"octahedral"})",
      R"({"levels":3,"base_size":32,"samples":48,"projection":"octahedral"})",
      R"({"levels":3,"base_size":16,"samples":64,"projection":"octahedral"})",
      R"({"levels":3,"base_size":16,"samples":48,"projection":"equal-area"})",
      R"({"levels":3,"base_size":16,"samples":48,"projection":"octahedral","format":"exr"})",
      R"({"levels":3,"base_size":16,"samples":48,"projection":"octahedral","precision":"float"})",
      R"({"levels":3,"base_size":16,"samples":48,"projection":"octahedral","level_roughness":"filament"})",
      R"({"base_size":16,"samples":48,"target":"gltf"})"};
  for (const std::string& other : others) {
    const Reply r = submit(white(), other);
    EXPECT_EQ(r.status, 202) << other;
    EXPECT_EQ(r.body_json()["reused"], false) << other;
    EXPECT_EQ(test::finished_job(shared_client(), r.header("Location"))["status"], "done");
  }
  const Reply forest = submit("forest_exr", body);
  EXPECT_EQ(forest.status, 202);
  EXPECT_EQ(test::finished_job(shared_client(), forest.header("Location"))["status"], "done");

  // Removed with DELETE: made again.
  EXPECT_EQ(del(url).status, 204);
  const Reply after_delete = submit(white(), body);
  EXPECT_EQ(after_delete.status, 202);
  EXPECT_NE(after_delete.header("Location"), url);
  EXPECT_EQ(test::finished_job(shared_client(), after_delete.header("Location"))["status"], "done");
}

TEST(PrefilterApi, ARunningJobIsReusedUntilItIsCancelled) {
  const std::string body = R"({"levels":11,"base_size":2048,"samples":512,"projection":"equal-area"})";
  const Reply first = submit("forest_exr", body);
  ASSERT_EQ(first.status, 202) << first.body;
  const std::string url = first.header("Location");
  const Reply again = submit("forest_exr", body);
  EXPECT_EQ(again.status, 200);
  EXPECT_EQ(again.header("Location"), url);
  EXPECT_EQ(again.body_json()["reused"], true);
  EXPECT_NE(again.body_json()["status"], "done");
  EXPECT_EQ(del(url).status, 202);
  // Cancelled (or cancelling): not reused.
  const Reply after_cancel = submit("forest_exr", body);
  EXPECT_EQ(after_cancel.status, 202);
  EXPECT_NE(after_cancel.header("Location"), url);
  EXPECT_EQ(del(after_cancel.header("Location")).status, 202);
  EXPECT_EQ(test::finished_job(shared_client(), url)["status"], "cancelled");
  EXPECT_EQ(test::finished_job(shared_client(), after_cancel.header("Location"))["status"], "cancelled");
  EXPECT_EQ(del(url).status, 204);
  EXPECT_EQ(del(after_cancel.header("Location")).status, 204);
}

TEST(PrefilterApi, BadInputIsA400NamingTheField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"levels":0})", "'levels'"},
      {R"({"levels":9,"base_size":256})", "'levels'"},
      {R"({"base_size":100000})", "'base_size'"},
      {R"({"samples":"many"})", "'samples'"},
      {R"({"format":"png"})", "'format'"},
      {R"({"precision":"double"})", "'precision'"},
      {R"({"projection":"mirror-ball"})", "'projection'"},
      {R"({"projection":"cross","base_size":40,"levels":5})", "'base_size'"},
      {R"({"roughness":1})", "'roughness'"},
  };
  for (const auto& [body, field] : cases) {
    const Reply r = submit(white(), body);
    EXPECT_EQ(r.status, 400) << body;
    EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field") << body;
    EXPECT_NE(r.body_json()["error"]["message"].get<std::string>().find(field), std::string::npos) << r.body;
  }
  const Reply not_json = submit(white(), "{levels: 3");
  EXPECT_EQ(not_json.status, 400);
  EXPECT_EQ(not_json.body_json()["error"]["code"], "invalid_json");
}

TEST(PrefilterApi, UnknownMapsJobsAndFilesAre404) {
  const Reply no_map = submit("no_such_map", "");
  EXPECT_EQ(no_map.status, 404);
  EXPECT_EQ(no_map.body_json()["error"]["code"], "not_found");
  EXPECT_EQ(shared_get("/api/v1/prefilters/0123456789abcdef").status, 404);
  EXPECT_EQ(del("/api/v1/prefilters/0123456789abcdef").status, 404);
  const json st = finished(white(), R"({"levels":2,"base_size":16,"samples":16})");
  ASSERT_EQ(st["status"], "done");
  const Reply no_file = shared_get("/api/v1/prefilters/" + st["id"].get<std::string>() + "/files/level0.exr");
  EXPECT_EQ(no_file.status, 404);
  EXPECT_NE(no_file.body_json()["error"]["message"].get<std::string>().find("prefiltered.ktx2"),
            std::string::npos);
}

// A target's job: the target's chain (a cube of the full pyramid for gltf), then its files, listed and
// served; a white map gives irradiance pi everywhere, E_00 = pi sqrt(4 pi) and no other coefficient.
TEST(PrefilterApi, ATargetsJobServesTheTargetsFiles) {
  const json st = finished(white(), R"({"base_size":16,"samples":40,"target":"gltf"})");
  ASSERT_EQ(st["status"], "done") << st;
  EXPECT_EQ(st["target"], "gltf");
  EXPECT_FALSE(st.contains("format"));
  EXPECT_EQ(st["projection"], "cube");
  EXPECT_EQ(st["levels"], 5);
  EXPECT_DOUBLE_EQ(st["level_info"][4]["roughness"].get<double>(), 1.0);
  std::vector<std::string> names;
  for (const json& f : st["files"]) names.push_back(f["name"]);
  // The .gltf, the KTX2 cube, EXT_lights_image_based's 6 PNG faces of each of the 5 levels, the manifest.
  ASSERT_EQ(names.size(), 2u + 6 * 5 + 1);
  EXPECT_EQ(names[0], "prefilter_white.gltf");
  EXPECT_EQ(names[1], "prefilter_white_radiance.ktx2");
  EXPECT_EQ(names[2], "prefilter_white_specular_0_0.png");
  EXPECT_EQ(names.back(), "manifest.json");
  const Reply face = shared_get(st["files"][2]["url"]);
  EXPECT_EQ(face.status, 200);
  EXPECT_EQ(face.type(), "image/png");
  const Reply gltf = shared_get(st["files"][0]["url"]);
  ASSERT_EQ(gltf.status, 200) << gltf.body;
  EXPECT_EQ(gltf.type(), "model/gltf+json");
  const json c =
      gltf.body_json()["extensions"]["KHR_lights_environment"]["lights"][0]["irradianceCoefficients"];
  ASSERT_EQ(c.size(), 9u);
  const double e00 = M_PI * std::sqrt(4 * M_PI);
  for (size_t j = 0; j < 9; ++j)
    for (size_t ch = 0; ch < 3; ++ch) EXPECT_NEAR(c[j][ch].get<double>(), j == 0 ? e00 : 0.0, 1e-9) << j;
  const Reply cube = shared_get(st["files"][1]["url"]);
  ASSERT_EQ(cube.status, 200);
  const Ktx2Texture t = read_ktx2(bytes_of(cube), {});
  EXPECT_EQ(t.faces, 6u);
  ASSERT_EQ(t.levels.size(), 5u);
  for (const Image& level : t.levels) expect_all_near(level, 1.0f, 2e-3f);
  const Reply manifest = shared_get(st["files"][names.size() - 1]["url"]);
  ASSERT_EQ(manifest.status, 200);
  EXPECT_EQ(manifest.body_json()["target"], "gltf");
  EXPECT_EQ(shared_get(st["files"][0]["url"].get<std::string>() + "x").status, 404);
}

TEST(PrefilterApi, AFieldATargetFixesIsA400NamingIt) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"target":"gltf","projection":"latlong"})", "field 'projection'"},
      {R"({"target":"gltf","levels":4})", "field 'levels'"},
      {R"({"target":"gltf","level_roughness":"filament"})", "field 'level_roughness'"},
      {R"({"target":"gltf","format":"exr"})", "field 'format'"},
      {R"({"target":"gltf","precision":"float"})", "field 'precision'"},
      {R"({"target":"gltf","base_size":48})", "field 'base_size'"},
      {R"({"target":"unity3d"})", "field 'target'"}};
  for (const auto& [body, field] : cases) {
    const Reply r = submit(white(), body);
    EXPECT_EQ(r.status, 400) << body;
    EXPECT_NE(r.body.find(field), std::string::npos) << r.body;
  }
  // The value the target makes may be given.
  const Reply same = submit(white(), R"({"target":"gltf","base_size":16,"levels":5,"projection":"cube"})");
  EXPECT_TRUE(same.status == 200 || same.status == 202) << same.body;
}

}  // namespace
}  // namespace lp

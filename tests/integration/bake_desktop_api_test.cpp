// The desktop targets through the prefilter job on the real server: a map whose colour tells the world
// direction uploaded, a job per target, its files listed and served, and the Godot panorama and Unreal
// lat-long read back from the served bytes with every texel the colour of the direction the engine
// samples there; a chain field the target fixes, or one a target without a chain is given, is a 400.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/image/image_io.hpp"
#include "support/engine_directions.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/shared_client.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;
using test::shared_client;

const std::string& direction_map_name() {
  static const std::string name = [] {
    const auto pfm = write_pfm(test::direction_map(64, 32));
    const Reply r = test::reply(shared_client().Post("/api/v1/envmaps?name=bake_directions",
                                                     reinterpret_cast<const char*>(pfm.data()), pfm.size(),
                                                     "application/octet-stream"));
    EXPECT_TRUE(r.status == 201 || r.status == 409) << r.body;
    return std::string("bake_directions");
  }();
  return name;
}

// Runs a job of `body` to its end (or finds the same job done before): its status URL and status.
std::pair<std::string, json> finished(const std::string& body) {
  const Reply r = test::reply(shared_client().Post(
      ("/api/v1/envmaps/" + direction_map_name() + "/prefilter").c_str(), body, "application/json"));
  EXPECT_TRUE(r.status == 202 || r.status == 200) << r.body;
  const std::string url = "/api/v1/prefilters/" + r.body_json()["id"].get<std::string>();
  const json done = test::finished_job(shared_client(), url);
  EXPECT_EQ(done["status"], "done") << done.dump();
  return {url, done};
}

std::string served(const std::string& job_url, const std::string& name) {
  const Reply file = test::reply(shared_client().Get((job_url + "/files/" + name).c_str()));
  EXPECT_EQ(file.status, 200) << name;
  return file.body;
}

Image image_of(const std::string& bytes) {
  return read_image({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}).image;
}

TEST(BakeDesktopApi, GodotJobServesItsPanoramaInGodotsFrameAndItsManifest) {
  const auto [url, status] = finished(R"({"target":"godot","base_size":16,"levels":3,"samples":64})");
  const Image pano = image_of(served(url, "bake_directions_panorama.exr"));
  EXPECT_EQ(test::texels_off_direction(pano, test::godot_panorama_texel, 4e-3f), 0);
  std::vector<std::string> names;
  for (const json& f : status["files"]) names.push_back(f["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"bake_directions_panorama.exr", "bake_directions_cubemap.exr",
                                             "bake_directions_radiance_astc.ktx2", "manifest.json"}));
  const json manifest = json::parse(served(url, "manifest.json"));
  EXPECT_EQ(manifest["target"], "godot");
  EXPECT_EQ(manifest["import"]["cubemap"]["slices/arrangement"], "6x1");
}

TEST(BakeDesktopApi, UnrealJobServesItsLatLongInUnrealsFrame) {
  const std::string url = finished(R"({"target":"unreal"})").first;
  const Image latlong = image_of(served(url, "bake_directions_latlong.hdr"));
  EXPECT_EQ(test::texels_off_direction(latlong, test::unreal_panorama_texel, 0.05f), 0);
}

TEST(BakeDesktopApi, FieldsATargetFixesOrDoesNotTakeAre400) {
  for (const auto& [body, field] : {std::pair{R"({"target":"unity","projection":"latlong"})", "projection"},
                                    {R"({"target":"godot","level_roughness":"filament"})", "level_roughness"},
                                    {R"({"target":"unreal","samples":64})", "samples"}}) {
    const Reply r = test::reply(shared_client().Post(
        ("/api/v1/envmaps/" + direction_map_name() + "/prefilter").c_str(), body, "application/json"));
    EXPECT_EQ(r.status, 400) << body;
    EXPECT_NE(r.body.find(field), std::string::npos) << r.body;
  }
}

}  // namespace
}  // namespace lp

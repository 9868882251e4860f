// `lightprobe info MAP`, the real tool on the committed maps: its figures are the engine's, its document the
// server's metadata of the same map, and a bad map fails with the API's code and exit status 2.
// `lightprobe info MODEL`: the description an asset's record gives of the same model, in the world frame,
// and invalid_model for a model that does not load.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

json info(const std::string& map) {
  const test::CliRun run = test::run_cli({"info", map});
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return json::parse(run.out);
}

TEST(CliInfo, FiguresAreTheEnginesForEveryRealMap) {
  for (const std::string& file : test::real_envmap_files()) {
    SCOPED_TRACE(file);
    const EnvMap map(read_image_file(test::envmap_path(file)).image);
    const json j = info(test::envmap_path(file).string());
    EXPECT_EQ(j["width"], test::kRealMapWidth);
    EXPECT_EQ(j["height"], test::kRealMapHeight);
    EXPECT_EQ(j["format"], test::envmap_path(file).extension().string().substr(1));
    for (int c = 0; c < 3; ++c) {
      // Printed as the float's shortest round-trip text: exact.
      EXPECT_EQ(j["power"][c].get<float>(), map.power()[c]);
      EXPECT_EQ(j["mean_radiance"][c].get<float>(), map.mean_radiance()[c]);
    }
    EXPECT_EQ(j["max_luminance"].get<float>(), map.max_luminance(LuminanceMode::Average));
    EXPECT_EQ(j["non_finite_pixels"], 0);
  }
}

TEST(CliInfo, MatchesTheServersMetadataOfTheSameMap) {
  const json cli = info(test::envmap_path("studio.hdr").string());
  const json api = test::reply(test::shared_server().client()->Get("/api/v1/envmaps/studio_hdr")).body_json();
  for (const char* key :
       {"width", "height", "format", "power", "mean_radiance", "illuminance", "max_luminance",
        "clamped_negative_values", "most_negative_value", "non_finite_pixels"})
    EXPECT_EQ(cli[key], api[key]) << key;
  EXPECT_EQ(cli["name"], "studio");
  EXPECT_FALSE(cli.contains("created"));
}

TEST(CliInfo, TheBuiltInSkyByName) {
  const json j = info("default");
  EXPECT_EQ(j["name"], "default");
  EXPECT_EQ(j["source"], "procedural");
  EXPECT_GT(j["width"].get<int>(), 0);
  EXPECT_GT(j["power"][0].get<double>(), 0.0);
}

TEST(CliInfo, ABadMapFailsWithTheApisCode) {
  const test::CliRun missing = test::run_cli({"info", "no-such-map.exr"});
  EXPECT_EQ(missing.exit_status, 2);
  EXPECT_EQ(missing.err, "error: not_found: cannot open no-such-map.exr\n");
  EXPECT_TRUE(missing.out.empty());

  const test::CliRun text = test::run_cli({"info", test::model_path("obj/quad.mtl").string()});
  EXPECT_EQ(text.exit_status, 2);
  EXPECT_EQ(text.err.rfind("error: unsupported_media_type: " + test::model_path("obj/quad.mtl").string(), 0),
            0u)
      << text.err;

  const test::CliRun policy = test::run_cli({"info", "default", "--invalid", "maybe"});
  EXPECT_EQ(policy.exit_status, 2);
  EXPECT_EQ(policy.err, "error: invalid_field: field 'invalid': 'maybe' is not one of: clamp, reject\n");
}

TEST(CliInfo, ATruncatedMapIsCorruptNeverACrash) {
  const auto bytes = test::read_bytes(test::envmap_path("forest.exr"));
  const test::TempDir dir;
  const std::string cut = (dir.path() / "truncated.exr").string();
  write_file(cut, std::span(bytes).first(bytes.size() / 2));
  const test::CliRun run = test::run_cli({"info", cut});
  EXPECT_EQ(run.exit_status, 2) << run.err;
  EXPECT_EQ(run.err.rfind("error: corrupt: " + cut + ": ", 0), 0u) << run.err;
}

// A model's description is its asset record's, without the asset's own fields (name, files, path...).
TEST(CliInfo, AModelsDescriptionIsItsAssetRecords) {
  const std::string glb = test::model_path("quad.glb").string();
  const json cli = info(glb);
  const auto bytes = test::read_bytes(glb);
  const test::Reply r = test::reply(test::shared_server().client()->Post(
      "/api/v1/assets?name=cli_info_quad", reinterpret_cast<const char*>(bytes.data()), bytes.size(),
      "application/octet-stream"));
  ASSERT_EQ(r.status, 201) << r.body;
  json record = r.body_json();
  for (const char* key : {"name", "model", "bytes", "files", "path", "created"}) record.erase(key);
  EXPECT_EQ(cli, record);
  EXPECT_EQ(cli["format"], "glb");
  EXPECT_EQ(cli["triangles"], 2);
  EXPECT_EQ(cli["bounds"]["min"], json::array({1.0, -3.0, 2.0}));  // the quad's, in the world frame
  EXPECT_EQ(cli["bounds"]["max"], json::array({3.0, -3.0, 4.0}));
}

TEST(CliInfo, AnObjModelHasItsObjectsAndMaterials) {
  const json j = info(test::model_path("obj/quad.obj").string());
  EXPECT_EQ(j["format"], "obj");
  EXPECT_EQ(j["triangles"], 2);
  // The unit square of the file's z = 0 plane, read y-up as a scene places it by default: world y = -z, z =
  // y.
  EXPECT_EQ(j["bounds"]["min"], json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(j["bounds"]["max"], json::array({1.0, 0.0, 1.0}));
  EXPECT_EQ(j["materials"][0]["name"], "textured");
  // OBJ/MTL states no side: both sides render
  EXPECT_EQ(j["materials"][0]["features"],
            json::array({"base_color_texture", "normal_texture", "double_sided"}));
}

TEST(CliInfo, ABrokenModelFailsWithInvalidModel) {
  const auto bytes = test::read_bytes(test::model_path("quad.glb"));
  const test::TempDir dir;
  const std::string cut = (dir.path() / "cut.glb").string();
  write_file(cut, std::span(bytes).first(bytes.size() / 2));
  const test::CliRun run = test::run_cli({"info", cut});
  EXPECT_EQ(run.exit_status, 2) << run.err;
  EXPECT_EQ(
      run.err,
      "error: invalid_model: glb cut.glb: its length is past the end of the file (1896 bytes declared, 948 "
      "present)\n");
  EXPECT_TRUE(run.out.empty());
}

}  // namespace
}  // namespace lp

// `lightprobe info MAP`, the real tool on the committed maps: its figures are the engine's, its document the
// server's metadata of the same map, and a bad map fails with the API's code and exit status 2.
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
  for (const char* key : {"width", "height", "format", "power", "mean_radiance", "max_luminance",
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

  const test::CliRun mesh = test::run_cli({"info", test::mesh_path("bunny.obj").string()});
  EXPECT_EQ(mesh.exit_status, 2);
  EXPECT_EQ(mesh.err.rfind("error: unsupported_media_type: " + test::mesh_path("bunny.obj").string(), 0), 0u)
      << mesh.err;

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

}  // namespace
}  // namespace lp

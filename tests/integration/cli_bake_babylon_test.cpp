// `lightprobe bake MAP --target babylon`, the real tool: NAME.env and manifest.json, the .env read back
// (read_babylon_env) with the full pyramid on Babylon's lod scale and the polynomial of the map's SH in
// Babylon's frame, the manifest stating frame, faces and each level's roughness, and the chain fields
// the target fixes refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "engine/image/babylon_env.hpp"
#include "engine/image/babylon_env_chain.hpp"
#include "support/cli_run.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

std::vector<uint8_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(CliBakeBabylon, WritesTheEnvAndItsManifest) {
  const test::TempDir dir;
  const std::string forest = test::envmap_path("forest.exr").string();
  const test::CliRun run = test::run_cli({"bake", forest, "--target", "babylon", "--out", dir.path().string(),
                                          "--base-size", "32", "--samples", "64", "-q"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"forest.env", "manifest.json"}));

  const BabylonEnv env = read_babylon_env(read_bytes(dir.path() / "forest.env"));
  EXPECT_EQ(env.width, 32);
  EXPECT_EQ(env.specular.size(), 6u * 6);  // 32 down to 1
  EXPECT_EQ(env.image_type, "image/png");
  EXPECT_EQ(env.lod_generation_scale, 0.8);

  const json manifest = json::parse(read_bytes(dir.path() / "manifest.json"));
  EXPECT_EQ(manifest["target"], "babylon");
  EXPECT_EQ(manifest["frame"]["world_to_engine"], json(kWorldToBabylon));
  EXPECT_EQ(manifest["face_order"]["faces"], json::array({"px", "nx", "py", "ny", "pz", "nz"}));
  const json& levels = manifest["roughness_to_lod"]["levels"];
  ASSERT_EQ(levels.size(), 6u);
  for (int i = 1; i < 6; ++i)  // HDRFiltering's alpha = 2^(i / 0.8) / size
    EXPECT_NEAR(levels[size_t(i)]["roughness"].get<double>(), std::sqrt(std::exp2(i / 0.8) / 32), 1e-12) << i;

  // The polynomial is the one of the manifest's SH (`lightprobe sh`'s radiance) in Babylon's frame.
  ShCoefficients sh;
  sh.bands = manifest["sh"]["bands"];
  for (const json& c : manifest["sh"]["radiance"]["coefficients"])
    sh.rgb.push_back({c["rgb"][0], c["rgb"][1], c["rgb"][2]});
  ASSERT_TRUE(env.irradiance);
  const BabylonSphericalPolynomial expected = babylon_polynomial(sh, kWorldToBabylon);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(env.irradiance->x[c], expected.x[c], 1e-9);
    EXPECT_NEAR(env.irradiance->yy[c], expected.yy[c], 1e-9);
    EXPECT_NEAR(env.irradiance->zx[c], expected.zx[c], 1e-9);
  }
}

TEST(CliBakeBabylon, RefusesTheFieldsTheTargetFixes) {
  const test::TempDir dir;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--base-size", "48"},
       "error: invalid_field: field 'base_size': must be a power of two for the target 'babylon' (Babylon's "
       ".env)\n"},
      {{"--base-size", "32", "--levels", "5"},
       "error: invalid_field: field 'levels': the target 'babylon' makes it 6, got 5\n"},
      {{"--projection", "latlong"},
       "error: invalid_field: field 'projection': the target 'babylon' makes it \"cube\", got \"latlong\"\n"},
      {{"--level-roughness", "linear"},
       "error: invalid_field: field 'level_roughness': the target 'babylon' makes it \"babylon\", got "
       "\"linear\"\n"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args = {"bake", "default", "--target", "babylon", "--out", "x"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, 2) << run.err;
    EXPECT_EQ(run.err, message);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace lp

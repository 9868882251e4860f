// `lightprobe bake`, the real tool: the bundle's files exist and parse (KTX2 reader, EXR loader, JSON),
// the SH JSON is `lightprobe sh`'s, the DFG table `lightprobe brdf-lut`'s, the manifest lists every
// file with its conventions, and failures are the other commands'.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/image/image_io.hpp"
#include "engine/image/ktx2.hpp"
#include "support/cli_run.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return json::parse(text.str());
}

// The SH answer without its timing.
json without_elapsed(json sh) {
  sh.erase("elapsed_ms");
  return sh;
}

TEST(CliBake, WritesTheBundleTheOtherCommandsWrite) {
  const test::TempDir dir;
  const auto out = dir.path() / "bundle" / "forest";  // made with its parent
  const std::string forest = test::envmap_path("forest.exr").string();
  const test::CliRun run = test::run_cli({"bake", forest, "--out", out.string(), "--projection", "cube",
                                          "--levels", "4", "--base-size", "32", "--samples", "64"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("bake 100%"), std::string::npos) << run.err;

  const json manifest = read_json(out / "manifest.json");
  EXPECT_EQ(manifest["map"]["name"], "forest");
  EXPECT_NE(manifest["frame"].get<std::string>().find("z up"), std::string::npos);

  const json sh = read_json(out / manifest["sh"]["name"].get<std::string>());
  const test::CliRun sh_run = test::run_cli({"sh", forest});
  ASSERT_EQ(sh_run.exit_status, 0);
  EXPECT_EQ(without_elapsed(sh), without_elapsed(json::parse(sh_run.out)));
  EXPECT_EQ(sh["bands"], 3);
  EXPECT_TRUE(sh.contains("irradiance"));
  EXPECT_EQ(manifest["sh"]["convention"], sh["convention"]);

  const json& chain = manifest["prefiltered"];
  EXPECT_EQ(chain["projection"], "cube");
  EXPECT_EQ(chain["format"], "ktx2");
  EXPECT_EQ(chain["levels"], 4);
  EXPECT_NE(chain["convention"]["cube_faces"].get<std::string>().find("+X, -X, +Y, -Y, +Z, -Z"),
            std::string::npos);
  ASSERT_EQ(chain["files"], json::array({"prefiltered.ktx2"}));
  const Ktx2Texture t = read_ktx2(test::read_bytes(out / "prefiltered.ktx2"), {});
  EXPECT_EQ(t.faces, 6u);
  ASSERT_EQ(t.levels.size(), 4u);
  for (size_t i = 0; i < t.levels.size(); ++i) {
    EXPECT_EQ(t.levels[i].width(), 32 >> i);
    EXPECT_EQ(t.levels[i].height(), 6 * (32 >> i));
    EXPECT_EQ(chain["level_info"][i]["size"], 32 >> i);
  }
  EXPECT_EQ(t.metadata.at("lightprobe.cube_faces"), chain["convention"]["cube_faces"]);

  const auto lut_file = dir.path() / "lut.exr";
  ASSERT_EQ(test::run_cli({"brdf-lut", "-o", lut_file.string()}).exit_status, 0);
  const Image want = read_image_file(lut_file).image;
  const Image lut = read_image_file(out / manifest["brdf_lut"]["name"].get<std::string>()).image;
  ASSERT_EQ(lut.width(), 128);
  ASSERT_EQ(lut.height(), 128);
  EXPECT_TRUE(std::equal(lut.data().begin(), lut.data().end(), want.data().begin()));
  EXPECT_EQ(manifest["brdf_lut"]["size"], 128);

  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(out)) ++files;
  EXPECT_EQ(files, 4u);  // sh.json, prefiltered.ktx2, brdf_lut.exr, manifest.json: nothing partial
}

TEST(CliBake, ExrLevelsQuietly) {
  const test::TempDir dir;
  const test::CliRun run = test::run_cli({"bake", "default", "--out", dir.path().string(), "--format", "exr",
                                          "--levels", "3", "--base-size", "16", "--samples", "16", "-q"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const json manifest = read_json(dir.path() / "manifest.json");
  ASSERT_EQ(manifest["prefiltered"]["files"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const Image level =
        read_image_file(dir.path() / manifest["prefiltered"]["files"][i].get<std::string>()).image;
    EXPECT_EQ(level.width(), 16 >> i);
    EXPECT_EQ(level.height(), 8 >> i);
  }
}

TEST(CliBake, FailsAsTheOtherCommandsFail) {
  const test::TempDir dir;
  const std::vector<std::tuple<std::vector<std::string>, int, std::string>> cases = {
      {{"bake", "default"},
       2,
       "error: bad_request: usage: lightprobe bake MAP --out DIR [--target NAME] [options] (see --help)\n"},
      {{"bake", "default", "--out", "x", "--levels", "20"},
       2,
       "error: invalid_field: field 'levels': must be in [1, 12], got 20\n"},
      {{"bake", "default", "--out", "x", "--projection", "sphere"},
       2,
       "error: invalid_field: field 'projection'"},
      {{"bake", "no_such_map.exr", "--out", "x"}, 2, "error: not_found: "},
      {{"bake", "default", "--out", "/proc/lightprobe-bake"}, 1, "error: write_failed: "},
  };
  for (const auto& [args, status, message] : cases) {
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, status) << run.err;
    EXPECT_EQ(run.err.rfind(message, 0), 0u) << run.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace lp

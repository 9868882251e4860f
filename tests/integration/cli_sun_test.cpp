// `lightprobe sun`, the real tool: the built-in sky's sun as the server finds it, the residual written
// to a file that holds the residual's power exactly, no sun and no file for a map without one, and bad
// options refused with the API's codes.
#include <gtest/gtest.h>

#include <filesystem>
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

json sun(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"sun"};
  all.insert(all.end(), args.begin(), args.end());
  const test::CliRun run = test::run_cli(all);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return json::parse(run.out);
}

TEST(CliSun, TheBuiltInSkysSunAsTheServerFindsIt) {
  const test::TempDir dir;
  const std::string residual = (dir.path() / "residual.exr").string();
  json cli = sun({"default", "--residual", residual, "--format", "json"});
  ASSERT_TRUE(cli["found"].get<bool>()) << cli.dump();
  EXPECT_EQ(cli["residual"], residual);
  const EnvMap written(read_image_file(residual).image);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(written.power()[c], cli["power"]["residual"][c].get<float>());

  const test::Reply r = test::reply(
      test::default_server().client()->Post("/api/v1/envmaps/default/sun", "", "application/json"));
  ASSERT_EQ(r.status, 200) << r.body;
  json api = r.body_json();
  EXPECT_EQ(api["residual"], "default-sun");
  for (json* j : {&cli, &api})
    for (const char* key : {"elapsed_ms", "cached", "residual"}) j->erase(key);
  EXPECT_EQ(cli, api);
}

TEST(CliSun, NoSunNoResidualFile) {
  const test::TempDir dir;
  const auto residual = dir.path() / "residual.pfm";
  const json j = sun({test::envmap_path("studio.exr").string(), "--residual", residual.string(),
                      "--max-radius-deg", "0.1", "--min-share", "0.9"});
  EXPECT_FALSE(j["found"].get<bool>());
  EXPECT_TRUE(j["residual"].is_null());
  EXPECT_FALSE(std::filesystem::exists(residual));
}

TEST(CliSun, HelpStatesTheApisRangesAndDefaults) {
  const std::string help = test::run_cli({"sun", "--help"}).out;
  EXPECT_NE(help.find("in [0.001, 1] (default 0.05)"), std::string::npos) << help;
  EXPECT_NE(help.find("in [0.05, 30] (default 5)"), std::string::npos) << help;
}

TEST(CliSun, BadOptionsFailWithTheApisCodes) {
  const test::CliRun threshold = test::run_cli({"sun", "default", "--threshold", "2"});
  EXPECT_EQ(threshold.exit_status, 2);
  EXPECT_EQ(threshold.err.rfind("error: invalid_field: field 'threshold': ", 0), 0u) << threshold.err;
  const test::CliRun residual = test::run_cli({"sun", "default", "--residual", "out.txt"});
  EXPECT_EQ(residual.exit_status, 2);
  EXPECT_EQ(residual.err.rfind("error: invalid_field: field 'residual': ", 0), 0u) << residual.err;
  const test::CliRun format = test::run_cli({"sun", "default", "--format", "csv"});
  EXPECT_EQ(format.exit_status, 2);
  EXPECT_EQ(format.err,
            "error: invalid_field: field 'format': 'csv' is not one of: json, mitsuba, blender, usd, gltf\n");
  const test::CliRun unknown = test::run_cli({"sun", "default", "--radius", "2"});
  EXPECT_EQ(unknown.exit_status, 2);
  EXPECT_EQ(unknown.err.rfind("error: invalid_field: field 'radius': unknown field", 0), 0u) << unknown.err;
}

}  // namespace
}  // namespace lp

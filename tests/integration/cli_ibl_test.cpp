// `lightprobe sh` and `lightprobe brdf-lut`, the real tool: the same coefficients and table as the
// server's answers, and bad options failing as the API fails them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

TEST(CliIbl, ShCoefficientsAreTheServers) {
  const test::CliRun run =
      test::run_cli({"sh", test::envmap_path("forest.exr").string(), "--bands", "4", "--window", "hann"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const json cli = json::parse(run.out);
  const json api =
      test::reply(test::shared_server().client()->Get("/api/v1/envmaps/forest_exr/sh?bands=4&window=hann"))
          .body_json();
  EXPECT_EQ(cli["radiance"], api["radiance"]);
  EXPECT_EQ(cli["irradiance"], api["irradiance"]);
  EXPECT_EQ(cli["lambertian"], api["lambertian"]);
  EXPECT_EQ(cli["convention"], api["convention"]);
  EXPECT_EQ(cli["radiance"]["coefficients"].size(), 16u);
}

TEST(CliIbl, TheLutFileIsTheServers) {
  const test::TempDir dir;
  const auto file = dir.path() / "lut.exr";
  const test::CliRun run =
      test::run_cli({"brdf-lut", "--size", "16", "--multiscatter", "true", "-o", file.string()});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const Image cli = read_image_file(file).image;
  const auto reply =
      test::reply(test::default_server().client()->Get("/api/v1/brdf-lut?size=16&multiscatter=true"));
  const Image api =
      read_image({reinterpret_cast<const uint8_t*>(reply.body.data()), reply.body.size()}).image;
  ASSERT_EQ(cli.width(), 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(cli.at(x, y), api.at(x, y));
}

TEST(CliIbl, BadOptionsFailAsTheApiAnswersThem) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"sh", "default", "--bands", "9"},
                                               {"sh", "default", "--window", "box"},
                                               {"sh", "default", "--colour", "red"},
                                               {"brdf-lut", "--size", "4", "-o", "x.exr"},
                                               {"brdf-lut", "--format", "jpg", "-o", "x.exr"}}) {
    const test::CliRun run = test::run_cli(args);
    EXPECT_EQ(run.exit_status, 2) << run.err;
    EXPECT_EQ(run.err.rfind("error: invalid_field: ", 0), 0u) << run.err;
  }
}

}  // namespace
}  // namespace lp

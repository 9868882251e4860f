// `lightprobe render MODEL --turntable N -o DIR`, the real tool: N frames of the requested size orbiting
// the framed model, and DIR/cameras.json with each frame's camera.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/png_pixels.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// The azimuth the camera looks from, in degrees: 0 from the front (-y), 90 from +x.
double azimuth_deg(const json& camera) {
  const double dx = camera["position"][0].get<double>() - camera["look_at"][0].get<double>();
  const double dy = camera["position"][1].get<double>() - camera["look_at"][1].get<double>();
  return std::atan2(dx, -dy) * 180 / M_PI;
}

double elevation_deg(const json& camera) {
  double horizontal = 0, d[3];
  for (int i = 0; i < 3; ++i) d[i] = camera["position"][i].get<double>() - camera["look_at"][i].get<double>();
  horizontal = std::hypot(d[0], d[1]);
  return std::atan2(d[2], horizontal) * 180 / M_PI;
}

TEST(CliTurntable, FourFramesAQuarterTurnApart) {
  const test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "frames");
  const test::CliRun run =
      test::run_cli({"render", test::model_path("quad.glb").string(), "--turntable", "4", "--width", "24",
                     "--height", "16", "--spp", "2", "-o", "frames/", "-q"},
                    dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.out, "");
  for (const std::string name : {"frame_0000.png", "frame_0001.png", "frame_0002.png", "frame_0003.png"}) {
    const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "frames" / name));
    EXPECT_EQ(png.width, 24) << name;
    EXPECT_EQ(png.height, 16) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames" / "frame_0004.png"));

  // The cameras as a turntable's status gives them.
  const json cameras = read_json(dir.path() / "frames" / "cameras.json");
  ASSERT_EQ(cameras.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const json& c = cameras[size_t(i)];
    EXPECT_EQ(c["index"], i);
    EXPECT_NEAR(std::remainder(azimuth_deg(c) - 90.0 * i, 360.0), 0.0, 1e-3);
    EXPECT_NEAR(elevation_deg(c), 15.0, 1e-3);  // the default elevation, no sweep
    EXPECT_EQ(c["fov_deg"], 40.0);
    // Row-major camera-to-world: its last column is the position, its third the direction from look_at to
    // the camera (the camera looks down its local -z).
    const std::vector<double> m = c["matrix"];
    ASSERT_EQ(m.size(), 16u);
    double distance = 0;
    for (int r = 0; r < 3; ++r)
      distance += std::pow(c["position"][r].get<double>() - c["look_at"][r].get<double>(), 2);
    distance = std::sqrt(distance);
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(m[size_t(4 * r + 3)], c["position"][r].get<double>(), 1e-5);
      const double back = (c["position"][r].get<double>() - c["look_at"][r].get<double>()) / distance;
      EXPECT_NEAR(m[size_t(4 * r + 2)], back, 1e-5);
    }
    EXPECT_EQ(std::vector<double>(m.begin() + 12, m.end()), (std::vector<double>{0, 0, 0, 1}));
  }
}

// The orbit's options move the cameras: a start, a step and an elevation of their own.
TEST(CliTurntable, TheOrbitsOptionsPlaceTheCameras) {
  const test::TempDir dir;
  const test::CliRun run = test::run_cli({"render",
                                          test::model_path("obj/quad.obj").string(),
                                          "--turntable",
                                          "3",
                                          "--azimuth-start-deg",
                                          "30",
                                          "--azimuth-step-deg",
                                          "10",
                                          "--elevation-deg",
                                          "40",
                                          "--width",
                                          "8",
                                          "--height",
                                          "8",
                                          "--spp",
                                          "1",
                                          "--format",
                                          "exr",
                                          "-o",
                                          dir.path().string(),
                                          "-q"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const json cameras = read_json(dir.path() / "cameras.json");
  ASSERT_EQ(cameras.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(azimuth_deg(cameras[size_t(i)]), 30.0 + 10.0 * i, 1e-3);
    EXPECT_NEAR(elevation_deg(cameras[size_t(i)]), 40.0, 1e-3);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / ("frame_000" + std::to_string(i) + ".exr")));
  }
}

TEST(CliTurntable, BadOrbitsAreRefusedBeforeRendering) {
  const test::TempDir dir;
  const std::string model = test::model_path("quad.glb").string();
  const test::CliRefusals cases = {
      {{"--turntable", "0", "-o", "."},
       "invalid_field: field 'turntable.frames': must be in [1, 720], got 0"},
      {{"--turntable", "4"}, "bad_request: --turntable writes its frames into a folder: give -o DIR"},
      {{"--elevation-deg", "20", "-o", "a.png"}, "bad_request: --elevation-deg needs --turntable N"},
  };
  test::expect_cli_refusals({"render", model}, cases, dir.path());
}

}  // namespace
}  // namespace lp

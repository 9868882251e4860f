// `lightprobe denoise`, the real tool on generated images: its output is the engine's denoiser's to the
// bit, noise goes, and bad inputs (a size mismatch, a normal without albedo, no weights) fail cleanly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "engine/denoise/denoiser.hpp"
#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/constant_map.hpp"
#include "support/noisy_images.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

void write_pfm(const Image& img, const std::filesystem::path& path) {
  const auto bytes = write_image(img, ImageFormat::Pfm);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

struct Inputs {
  test::TempDir dir;
  Image clean = test::smooth_gradient(160, 120), color = test::with_exponential_noise(clean, 5);
  Image albedo = test::constant_image(160, 120, {0.7f, 0.7f, 0.7f}),
        normal = test::constant_image(160, 120, {0.f, 0.f, 1.f});
  Inputs() {
    write_pfm(color, path("color.pfm"));
    write_pfm(albedo, path("albedo.pfm"));
    write_pfm(normal, path("normal.pfm"));
    write_pfm(test::constant_image(80, 120, {1, 1, 1}), path("small.pfm"));
  }
  std::string path(const char* name) const { return (dir.path() / name).string(); }
};

TEST(CliDenoise, WritesTheEnginesResult) {
  const Inputs in;
  const test::TempDir out;
  const test::CliRun run =
      test::run_cli({"denoise", in.path("color.pfm"), "-o", "clean.exr", "--albedo", in.path("albedo.pfm"),
                     "--normal", in.path("normal.pfm"), "--threads", "1"},
                    out.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const Image written = read_image_file(out.path() / "clean.exr").image;
  const Image expected = denoise::Denoiser().run({&in.color, &in.albedo, &in.normal});
  ASSERT_EQ(written.width(), 160);
  ASSERT_EQ(written.height(), 120);
  for (size_t i = 0; i < expected.data().size(); ++i) ASSERT_EQ(written.data()[i], expected.data()[i]) << i;
  EXPECT_LT(test::rel_mse(written, in.clean), test::rel_mse(in.color, in.clean) / 20);
}

TEST(CliDenoise, LdrColourAlone) {
  const Inputs in;
  const test::CliRun run =
      test::run_cli({"denoise", in.path("color.pfm"), "-o", "-", "--format", "pfm", "--ldr"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const Image written =
      read_image(std::span(reinterpret_cast<const uint8_t*>(run.out.data()), run.out.size())).image;
  for (float v : written.data()) ASSERT_TRUE(v >= 0 && v <= 1) << v;
}

TEST(CliDenoise, BadInputsFailCleanly) {
  const Inputs in;
  const test::TempDir out;
  test::expect_cli_refusals(
      {"denoise", in.path("color.pfm"), "-o", "x.exr"},
      {{{"--normal", in.path("normal.pfm")},
        "bad_request: --normal needs --albedo (OIDN has no colour+normal filter)"},
       {{"--albedo", in.path("small.pfm")}, "bad_request: the albedo is 80x120, the colour 160x120"},
       {{"--albedo", in.path("albedo.pfm"), "--normal", in.path("small.pfm")},
        "bad_request: the normal is 80x120, the colour 160x120"}},
      out.path());
  setenv("LIGHTPROBE_DENOISE_WEIGHTS", "/nonexistent", 1);
  const test::CliRun run = test::run_cli({"denoise", in.path("color.pfm"), "-o", "x.exr"}, out.path());
  unsetenv("LIGHTPROBE_DENOISE_WEIGHTS");
  EXPECT_EQ(run.exit_status, 2);
  EXPECT_EQ(run.err,
            "error: not_found: denoiser weights not found in /nonexistent (set LIGHTPROBE_DENOISE_WEIGHTS "
            "to the folder of the rt_*.tza files)\n");
  EXPECT_TRUE(std::filesystem::is_empty(out.path()));
}

}  // namespace
}  // namespace lp

// `lightprobe render ... --denoise`, the real tool and its real denoiser: the denoised picture of a 2 spp
// render of the `materials` preset is nearer a 512 spp render than the raw one; a turntable's frames are
// denoised unless --no-denoise; the two switches together are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/image_error.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;

// The scene file of a small render of the materials preset under the forest map.
fs::path write_scene(const fs::path& dir) {
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"envmap":")" << test::envmap_path("forest.exr").string()
                       << R"(","scene":{"preset":"materials"},"width":64,"height":48,"seed":3})";
  return scene;
}

Image rendered(const fs::path& dir, std::vector<std::string> options, const std::string& file) {
  std::vector<std::string> args = {"render", write_scene(dir).string(), "-q", "-o", file};
  args.insert(args.end(), options.begin(), options.end());
  const test::CliRun run = test::run_cli(args, dir);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return read_image_file(dir / file, ImageLimits{}).image;
}

TEST(CliDenoiseRender, TheDenoisedPictureIsNearerAConvergedRenderThanTheRawOne) {
  const test::TempDir dir;
  const Image reference = rendered(dir.path(), {"--spp", "512"}, "reference.exr");
  const Image raw = rendered(dir.path(), {"--spp", "2"}, "raw.exr");
  const Image denoised = rendered(dir.path(), {"--spp", "2", "--denoise"}, "denoised.exr");
  const double raw_error = test::rel_mse(raw, reference), denoised_error = test::rel_mse(denoised, reference);
  std::cout << "the tool, materials at 2 spp against 512 spp: relMSE raw " << raw_error << ", denoised "
            << denoised_error << "\n";
  EXPECT_LT(denoised_error, 0.25 * raw_error);
  // --no-denoise is the raw render, the default of a render.
  const Image off = rendered(dir.path(), {"--spp", "2", "--no-denoise"}, "off.exr");
  EXPECT_EQ(test::rel_mse(off, raw), 0.0);
}

TEST(CliDenoiseRender, ATurntableIsDenoisedUnlessNoDenoise) {
  const test::TempDir dir;
  const auto frame = [&](const std::string& folder, std::vector<std::string> options) {
    fs::create_directories(dir.path() / folder);
    std::vector<std::string> args = {
        "render",    write_scene(dir.path()).string(), "--turntable", "1", "--format", "pfm", "-q", "-o",
        folder + "/"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, 0) << run.err;
    return read_image_file(dir.path() / folder / "frame_0000.pfm", ImageLimits{}).image;
  };
  const Image denoised = frame("denoised", {"--spp", "2"}),
              raw = frame("raw", {"--spp", "2", "--no-denoise"});
  const Image reference = frame("reference", {"--spp", "512", "--no-denoise"});
  const double raw_error = test::rel_mse(raw, reference), denoised_error = test::rel_mse(denoised, reference);
  std::cout << "a turntable's frame at 2 spp against 512 spp: relMSE raw " << raw_error << ", denoised "
            << denoised_error << "\n";
  EXPECT_LT(denoised_error, 0.25 * raw_error);
}

TEST(CliDenoiseRender, BothSwitchesTogetherAreRefused) {
  const test::TempDir dir;
  const test::CliRun run = test::run_cli(
      {"render", write_scene(dir.path()).string(), "--denoise", "--no-denoise", "-o", "x.png"}, dir.path());
  EXPECT_EQ(run.exit_status, 2);
  EXPECT_NE(run.err.find("bad_request"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

}  // namespace
}  // namespace lp

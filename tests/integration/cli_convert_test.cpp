// `lightprobe convert IN OUT`, the real tool on committed maps: float formats round-trip exactly, PNG is
// tone mapped with the API's exposure and gamma, and bad files or names fail cleanly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/png_pixels.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

void expect_same_pixels(const Image& a, const Image& b) {
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(a.at(x, y)[c], b.at(x, y)[c]) << x << "," << y << " channel " << c;
}

TEST(CliConvert, ExrToPfmToExrIsExact) {
  const test::TempDir dir;
  const auto source = test::envmap_path("forest.exr");
  const test::CliRun to_pfm = test::run_cli({"convert", source.string(), "forest.pfm"}, dir.path());
  ASSERT_EQ(to_pfm.exit_status, 0) << to_pfm.err;
  const test::CliRun to_exr = test::run_cli({"convert", "forest.pfm", "back.EXR"}, dir.path());
  ASSERT_EQ(to_exr.exit_status, 0) << to_exr.err;
  const DecodedImage pfm = read_image_file(dir.path() / "forest.pfm");
  const DecodedImage back = read_image_file(dir.path() / "back.EXR");
  EXPECT_EQ(pfm.format, ImageFormat::Pfm);
  EXPECT_EQ(back.format, ImageFormat::Exr);
  const Image original = read_image_file(source).image;
  expect_same_pixels(pfm.image, original);
  expect_same_pixels(back.image, original);
}

// RGBE keeps 8 bits of mantissa per pixel: every channel within 1% of the largest channel of its pixel.
TEST(CliConvert, HdrToStandardOutputKeepsRgbePrecision) {
  const auto source = test::envmap_path("studio.exr");
  const test::CliRun run = test::run_cli({"convert", source.string(), "-", "--format", "hdr"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const DecodedImage hdr =
      read_image(std::span(reinterpret_cast<const uint8_t*>(run.out.data()), run.out.size()));
  EXPECT_EQ(hdr.format, ImageFormat::Hdr);
  const Image original = read_image_file(source).image;
  ASSERT_EQ(hdr.image.width(), original.width());
  for (int y = 0; y < original.height(); ++y)
    for (int x = 0; x < original.width(); ++x) {
      const Rgb o = original.at(x, y);
      const float largest = std::max({o.x, o.y, o.z});
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(hdr.image.at(x, y)[c], o[c], 0.01f * largest + 1e-30f);
    }
}

// Exposure +2 multiplies by 4, gamma 2 takes the square root: a pixel of radiance v becomes
// round(255 * min(1, sqrt(4 v))).
TEST(CliConvert, PngWithExposureAndGamma) {
  const test::TempDir dir;
  const auto source = test::envmap_path("forest.exr");
  const test::CliRun run = test::run_cli(
      {"convert", source.string(), "forest.png", "--exposure", "2", "--gamma", "2"}, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "forest.png"));
  const Image original = read_image_file(source).image;
  ASSERT_EQ(png.width, original.width());
  ASSERT_EQ(png.height, original.height());
  for (int y = 0; y < original.height(); ++y)
    for (int x = 0; x < original.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double expected = 255 * std::min(1.0, std::sqrt(4.0 * std::max(0.0f, original.at(x, y)[c])));
        ASSERT_NEAR(png.rgb[size_t((y * png.width + x) * 3 + c)], expected, 0.51) << x << "," << y;
      }
}

TEST(CliConvert, BadInputFailsCleanlyAndLeavesNoFile) {
  const test::TempDir dir;
  const auto source = test::envmap_path("forest.exr").string();
  const test::CliRun jpeg = test::run_cli({"convert", source, "forest.jpg"}, dir.path());
  EXPECT_EQ(jpeg.exit_status, 2);
  EXPECT_EQ(
      jpeg.err,
      "error: bad_request: cannot tell an image format from the name 'forest.jpg': give --format (png, exr, "
      "pfm, hdr)\n");
  const test::CliRun gamma = test::run_cli({"convert", source, "forest.png", "--gamma", "0"}, dir.path());
  EXPECT_EQ(gamma.exit_status, 2);
  EXPECT_EQ(gamma.err,
            "error: invalid_field: field 'gamma': must be > 0 (leave it out for the sRGB curve)\n");
  const test::CliRun mesh =
      test::run_cli({"convert", test::mesh_path("bunny.obj").string(), "bunny.exr"}, dir.path());
  EXPECT_EQ(mesh.exit_status, 2);
  EXPECT_EQ(mesh.err.rfind("error: unsupported_media_type: ", 0), 0u) << mesh.err;
  const test::CliRun unwritable = test::run_cli({"convert", source, "no/such/folder/out.exr"}, dir.path());
  EXPECT_EQ(unwritable.exit_status, 1);
  EXPECT_EQ(unwritable.err.rfind("error: write_failed: cannot create 'no/such/folder/out.exr", 0), 0u)
      << unwritable.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace lp

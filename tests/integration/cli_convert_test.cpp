// `lightprobe convert IN OUT`, the real tool on committed maps: float formats round-trip exactly, PNG is
// tone mapped with the API's exposure and gamma, maps change projection and back keeping their power, and
// bad files, names and projections fail cleanly with the API's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/projection/projection_texels.hpp"
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

// --tone-mapping reinhard takes each channel v to v / (1 + v) before the gamma: round(255 sqrt(v / (1 + v))).
// A name that is no curve fails as the API answers it.
TEST(CliConvert, PngWithAToneCurve) {
  const test::TempDir dir;
  const auto source = test::envmap_path("forest.exr");
  const test::CliRun run = test::run_cli(
      {"convert", source.string(), "forest.png", "--tone-mapping", "reinhard", "--gamma", "2"}, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::PngPixels png = test::decode_png(test::read_bytes(dir.path() / "forest.png"));
  const Image original = read_image_file(source).image;
  ASSERT_EQ(png.width, original.width());
  for (int y = 0; y < original.height(); ++y)
    for (int x = 0; x < original.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = std::max(0.0f, original.at(x, y)[c]);
        ASSERT_NEAR(png.rgb[size_t((y * png.width + x) * 3 + c)], 255 * std::sqrt(v / (1 + v)), 0.51)
            << x << "," << y;
      }
  const test::CliRun bad =
      test::run_cli({"convert", source.string(), "bad.png", "--tone-mapping", "filmic"}, dir.path());
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_EQ(
      bad.err,
      "error: invalid_field: field 'tone_mapping': 'filmic' is not one of: standard, neutral, agx, aces, "
      "reinhard\n");
}

TEST(CliConvert, BadInputFailsCleanlyAndLeavesNoFile) {
  const test::TempDir dir;
  const auto source = test::envmap_path("forest.exr").string();
  const test::CliRun tiff = test::run_cli({"convert", source, "forest.tif"}, dir.path());
  EXPECT_EQ(tiff.exit_status, 2);
  EXPECT_EQ(
      tiff.err,
      "error: bad_request: cannot tell an image format from the name 'forest.tif': give --format (png, exr, "
      "pfm, hdr, jpeg, webp)\n");
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

double relative_error(Rgb a, Rgb b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(a[c]) - b[c]) / double(b[c]));
  return worst;
}

// Lat-long -> cross -> lat-long, and lat-long -> equal-area -> octahedral -> lat-long, on the real tool: the
// shapes the help states and the map's power at every step.
TEST(CliConvert, ProjectionsAndBackKeepThePower) {
  const test::TempDir dir;
  const auto source = test::envmap_path("city.exr");  // 256 x 128
  const Rgb power = EnvMap::power_of(read_image_file(source).image);
  const auto convert = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "convert");
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, 0) << run.err;
  };
  convert({source.string(), "cross.exr", "--projection", "cross"});
  const Image cross = read_image_file(dir.path() / "cross.exr").image;
  EXPECT_EQ(cross.width(), 256);
  EXPECT_EQ(cross.height(), 192);
  EXPECT_LT(relative_error(projected_power(cross, Projection::Cross), power), 1e-4);
  convert({"cross.exr", "back.pfm", "--input-projection", "cross"});
  const Image back = read_image_file(dir.path() / "back.pfm").image;
  EXPECT_EQ(back.width(), 256);
  EXPECT_EQ(back.height(), 128);
  EXPECT_LT(relative_error(EnvMap::power_of(back), power), 1e-4);

  convert({source.string(), "ea.exr", "--projection", "equal-area", "--size", "96"});
  convert({"ea.exr", "oct.exr", "--input-projection", "equal-area", "--projection", "octahedral"});
  const Image oct = read_image_file(dir.path() / "oct.exr").image;
  EXPECT_EQ(oct.width(), 96);
  EXPECT_LT(relative_error(projected_power(oct, Projection::Octahedral), power), 1e-4);
  convert({"oct.exr", "oct_back.exr", "--input-projection", "octahedral"});
  EXPECT_EQ(read_image_file(dir.path() / "oct_back.exr").image.width(), 192);

  convert({source.string(), "py.pfm", "--projection", "cube", "--face", "py", "--size", "16"});
  const Image py = read_image_file(dir.path() / "py.pfm").image;
  EXPECT_EQ(py.width(), 16);
  EXPECT_EQ(py.height(), 16);
}

TEST(CliConvert, BadProjectionsFailWithTheApisErrors) {
  const test::TempDir dir;
  const std::string source = test::envmap_path("forest.exr").string();  // 256 x 128
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--projection", "mercator"},
       "invalid_field: field 'projection': 'mercator' is not one of: latlong, cube, cross, octahedral, "
       "equal-area"},
      {{"--input-projection", "cross"},
       "invalid_field: field 'input_projection': the image must be 4:3 (4N x 3N pixels) for projection "
       "cross, got "
       "256 x 128"},
      {{"--input-projection", "equal-area"},
       "invalid_field: field 'input_projection': the image must be square (N x N pixels) for projection "
       "equal-area, got 256 x 128"},
      {{"--size", "64"},
       "invalid_field: field 'size': applies to the projections cube, cross, octahedral and equal-area; "
       "latlong "
       "is the map as it is held"},
      {{"--projection", "cube", "--size", "1"}, "invalid_field: field 'size': must be in [2, 8192], got 1"},
      {{"--projection", "cross", "--face", "px"},
       "invalid_field: field 'face': applies to projection=cube only"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args = {"convert", source, "out.exr"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, 2) << message;
    EXPECT_EQ(run.err, "error: " + message + "\n");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace lp

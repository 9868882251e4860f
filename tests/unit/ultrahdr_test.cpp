// Ultra HDR gain-map JPEG: the radiance comes back from the file within the gain map's quantisation, the
// container is laid out where three.js's UltraHDRLoader reads it, and broken files are refused cleanly.
#include "engine/image/ultrahdr.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>

#include "engine/core/error.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

// Radiance over 2^-8 .. 2^12 along x, a different colour balance along y: smooth, like a sky.
Image ramp(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = std::exp2(-8.0f + 20.0f * float(x) / float(w - 1));
      const float t = float(y) / float(h - 1);
      img.set(x, y, {v, v * (0.25f + 0.75f * t), v * (1.0f - 0.75f * t)});
    }
  return img;
}

// How far a value may come back: the gain codes step (max - min) / 255 stops; rounding to the nearest
// code costs half a step and the gain map's JPEG (quality 100, 4:4:4, channels untransformed) rounds
// its DCT by at most one code more (1.51 steps measured on all three maps here): 2 steps, relative;
// below the offsets (1/64) the same share of the offset, absolute.
double tolerance(const ultrahdr::GainMapParams& p, double value) {
  const double steps = 2.0 * (p.gain_map_max - p.gain_map_min) / 255.0;
  return (std::exp2(steps) - 1.0) * (value + p.offset_hdr);
}

void expect_reconstructs(const Image& source, const DecodedUltraHdr& decoded) {
  ASSERT_EQ(decoded.radiance.width(), source.width());
  ASSERT_EQ(decoded.radiance.height(), source.height());
  int over = 0;
  double worst = 0;
  for (int y = 0; y < source.height(); ++y)
    for (int x = 0; x < source.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double want = source.at(x, y)[c], got = decoded.radiance.at(x, y)[c];
        const double share = std::abs(got - want) / tolerance(decoded.params, want);
        worst = std::max(worst, share);
        over += share > 1.0;
      }
  EXPECT_EQ(over, 0) << "values outside the tolerance; worst at " << worst << " of it";
}

TEST(UltraHdr, RampComesBackWithinTheGainQuantisation) {
  const Image source = ramp(256, 64);
  const DecodedUltraHdr decoded = decode_ultrahdr(encode_ultrahdr(source));
  // The boost covers the ramp's top (2^12 over SDR white) and nothing far beyond it.
  EXPECT_NEAR(decoded.params.gain_map_max, 12.0, 0.05);
  EXPECT_LE(decoded.params.gain_map_min, 0.0);
  EXPECT_GT(decoded.params.gain_map_min, -0.5);
  EXPECT_DOUBLE_EQ(decoded.params.gamma, 1.0);
  expect_reconstructs(source, decoded);
}

TEST(UltraHdr, RealMapWithASunComesBack) {
  const Image source = read_image_file(test::envmap_path("sunrise.exr")).image;
  const DecodedUltraHdr decoded = decode_ultrahdr(encode_ultrahdr(source));
  EXPECT_GT(decoded.params.gain_map_max, 12.0);  // the sun, over 2^12 times SDR white
  expect_reconstructs(source, decoded);
}

TEST(UltraHdr, SdrMapNeedsNoGain) {
  Image source(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) source.set(x, y, {0.5f * float(x) / 63.0f, 0.25f, float(y) / 31.0f});
  const DecodedUltraHdr decoded = decode_ultrahdr(encode_ultrahdr(source));
  EXPECT_LT(decoded.params.gain_map_max, 0.5);  // only what corrects the base's JPEG loss
  expect_reconstructs(source, decoded);
}

uint32_t be32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 | b[at + 3];
}

// three.js r187 reads the MPF APP2 segment from its length field: the primary's size and offset at 60
// and 64, the gain map's size at 76 and its offset at 80 (from the TIFF header, 6 bytes on).
TEST(UltraHdr, MpfIndexIsWhereThreeJsReadsIt) {
  const std::vector<uint8_t> file = encode_ultrahdr(ramp(64, 16));
  ASSERT_EQ(file[0], 0xFF);
  ASSERT_EQ(file[1], 0xD8);
  ASSERT_EQ(file[2], 0xFF);
  ASSERT_EQ(file[3], 0xE1);  // the XMP packet first
  const size_t app2 = 2 + 2 + (size_t(file[4]) << 8 | file[5]);
  ASSERT_EQ(file[app2], 0xFF);
  ASSERT_EQ(file[app2 + 1], 0xE2);
  const size_t length_field = app2 + 2;
  EXPECT_EQ(std::string_view(reinterpret_cast<const char*>(&file[length_field + 2]), 4),
            std::string_view("MPF\0", 4));
  EXPECT_EQ(std::string_view(reinterpret_cast<const char*>(&file[length_field + 6]), 4),
            std::string_view("MM\0*", 4));
  const uint32_t primary_size = be32(file, length_field + 60), primary_offset = be32(file, length_field + 64);
  const uint32_t gain_size = be32(file, length_field + 76);
  const size_t gain_at = be32(file, length_field + 80) + length_field + 6;
  EXPECT_EQ(primary_offset, 0u);
  EXPECT_EQ(primary_size, gain_at);
  ASSERT_EQ(gain_at + gain_size, file.size());
  EXPECT_EQ(file[gain_at], 0xFF);
  EXPECT_EQ(file[gain_at + 1], 0xD8);
  EXPECT_EQ(file[gain_at + 2], 0xFF);
  EXPECT_EQ(file[gain_at + 3], 0xE1);  // the gain map's hdrgm XMP
  const std::string text(file.begin() + long(gain_at), file.end());
  EXPECT_NE(text.find("hdrgm:Version=\"1.0\""), std::string::npos);
  EXPECT_NE(text.find("hdrgm:GainMapMax=\""), std::string::npos);
}

TEST(UltraHdr, BrokenFilesAreRefused) {
  const std::vector<uint8_t> file = encode_ultrahdr(ramp(64, 16));
  const auto refuses = [](std::span<const uint8_t> bytes) {
    try {
      decode_ultrahdr(bytes);
    } catch (const Error& e) {
      return e.kind() == ErrorKind::Corrupt;
    }
    return false;
  };
  EXPECT_TRUE(refuses(std::span(file).first(file.size() / 2)));  // the gain map cut off
  EXPECT_TRUE(refuses(std::span(file).first(40)));               // inside the XMP
  EXPECT_TRUE(refuses({}));
  std::vector<uint8_t> no_mpf = file;
  const size_t app2 = 2 + 2 + (size_t(file[4]) << 8 | file[5]);
  no_mpf[app2 + 4] = 'X';  // "MPF\0" -> "XPF\0"
  EXPECT_TRUE(refuses(no_mpf));
}

}  // namespace
}  // namespace lp

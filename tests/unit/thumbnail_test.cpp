// The 8-bit encoders (JPEG, WebP, animated WebP) decode back to their pictures (RGBA as JPEG over white);
// thumbnails keep the aspect, never enlarge, and keep a picture's mean radiance; contact sheets tile frames
// in order.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <webp/decode.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/image/contact_sheet.hpp"
#include "engine/image/encode_pixels8.hpp"
#include "engine/image/jpeg.hpp"
#include "engine/image/resize.hpp"
#include "engine/image/webp.hpp"

namespace lp {
namespace {

std::vector<uint8_t> gradient(int width, int height, int channels) {
  std::vector<uint8_t> bytes(size_t(width * height * channels));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        bytes[size_t((y * width + x) * channels + c)] =
            uint8_t(c == 3 ? (x < width / 2 ? 0 : 255) : (x * 4 + y * 2 + c * 40) % 256);
  return bytes;
}

TEST(Thumbnail, JpegDecodesToItsSizeAndNearItsPixels) {
  const auto pixels = gradient(40, 24, 3);
  const auto jpeg = encode_jpeg({pixels, 40, 24, 3});
  int w = 0, h = 0, n = 0;
  uint8_t* back = stbi_load_from_memory(jpeg.data(), int(jpeg.size()), &w, &h, &n, 3);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(w, 40);
  EXPECT_EQ(h, 24);
  double error = 0;
  for (size_t i = 0; i < pixels.size(); ++i) error += std::abs(double(back[i]) - double(pixels[i]));
  stbi_image_free(back);
  EXPECT_LT(error / double(pixels.size()), 4.0);  // quality 90: a few steps on a smooth ramp
}

TEST(Thumbnail, WebpKeepsAlpha) {
  const auto pixels = gradient(32, 16, 4);
  const auto webp = encode_webp({pixels, 32, 16, 4});
  int w = 0, h = 0;
  uint8_t* back = WebPDecodeRGBA(webp.data(), webp.size(), &w, &h);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(w, 32);
  EXPECT_EQ(h, 16);
  EXPECT_EQ(back[(5 * 32 + 2) * 4 + 3], 0);     // the left half transparent
  EXPECT_EQ(back[(5 * 32 + 30) * 4 + 3], 255);  // the right half opaque
  WebPFree(back);
}

// JPEG has no alpha: an RGBA picture is shown over white (its transparent half white, its opaque half its
// colour), as a white page shows it; PNG keeps the alpha.
TEST(Thumbnail, RgbaIsJpegOverWhiteAndPngWithAlpha) {
  const auto pixels = gradient(32, 16, 4);
  const auto jpeg = encode_pixels8({pixels, 32, 16, 4}, ImageFormat::Jpeg);
  int w = 0, h = 0, n = 0;
  uint8_t* back = stbi_load_from_memory(jpeg.data(), int(jpeg.size()), &w, &h, &n, 0);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(n, 3);
  double transparent = 0, opaque = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t at = size_t((y * 32 + x) * 3 + c);
        if (x < 12) transparent += std::abs(double(back[at]) - 255.0);
        if (x >= 20) opaque += std::abs(double(back[at]) - double(pixels[size_t((y * 32 + x) * 4 + c)]));
      }
  stbi_image_free(back);
  EXPECT_LT(transparent / (12 * 16 * 3), 2.0);
  EXPECT_LT(opaque / (12 * 16 * 3), 4.0);

  const auto png = encode_pixels8({pixels, 32, 16, 4}, ImageFormat::Png);
  uint8_t* rgba = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &n, 0);
  ASSERT_NE(rgba, nullptr);
  EXPECT_EQ(n, 4);
  EXPECT_TRUE(std::equal(pixels.begin(), pixels.end(), rgba));
  stbi_image_free(rgba);
}

TEST(Thumbnail, EncodersRefuseWrongSizes) {
  const auto pixels = gradient(8, 8, 3);
  EXPECT_THROW(encode_jpeg({pixels, 8, 9, 3}), Error);
  EXPECT_THROW(encode_webp({pixels, 8, 8, 4}), Error);
  EXPECT_THROW(encode_pixels8({pixels, 8, 8, 3}, ImageFormat::Exr), Error);
  const Pixels8 frame{pixels, 8, 8, 3};
  EXPECT_THROW(encode_webp_animation(std::span<const Pixels8>(&frame, 1), 0), Error);
}

TEST(Thumbnail, FittedSizeKeepsAspectAndNeverEnlarges) {
  EXPECT_EQ(fitted_size(64, 32, 16), (Size2{16, 8}));
  EXPECT_EQ(fitted_size(32, 64, 16), (Size2{8, 16}));
  EXPECT_EQ(fitted_size(64, 32, 1000), (Size2{64, 32}));
  EXPECT_EQ(fitted_size(64, 32, std::nullopt), (Size2{64, 32}));
  EXPECT_EQ(fitted_size(300, 2, 10), (Size2{10, 1}));  // a side never rounds to 0
  EXPECT_EQ(fitted_size(100, 30, 10), (Size2{10, 3}));
}

// Downscaling in linear light keeps the mean radiance of a picture of fine detail (a one-pixel
// checker of 0 and 4): its thumbnail is 2 everywhere, where averaging sRGB values would darken it.
TEST(Thumbnail, DownscaleKeepsMeanRadiance) {
  Image checker(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) checker.set(x, y, Rgb{1, 1, 1} * float(((x + y) % 2) * 4));
  const Image small = fit_longest_side(checker, 16);
  ASSERT_EQ(small.width(), 16);
  ASSERT_EQ(small.height(), 8);
  for (int y = 1; y < 7; ++y)
    for (int x = 1; x < 15; ++x) EXPECT_NEAR(small.at(x, y).x, 2.0f, 0.02f) << x << "," << y;
}

TEST(Thumbnail, ContactSheetTilesInOrder) {
  EXPECT_EQ(contact_sheet_layout(4).columns, 2);
  EXPECT_EQ(contact_sheet_layout(5).columns, 3);
  EXPECT_EQ(contact_sheet_layout(5).rows, 2);
  EXPECT_EQ(contact_sheet_layout(36).columns, 6);
  std::vector<std::vector<uint8_t>> frames;
  std::vector<Pixels8> pictures;
  for (int i = 0; i < 5; ++i) frames.emplace_back(size_t(2 * 3 * 3), uint8_t(10 * (i + 1)));
  for (const auto& f : frames) pictures.push_back({f, 2, 3, 3});
  const auto sheet = contact_sheet(pictures, contact_sheet_layout(5));
  ASSERT_EQ(sheet.size(), size_t(6 * 6 * 3));
  const auto at = [&](int x, int y) { return sheet[size_t((y * 6 + x) * 3)]; };
  EXPECT_EQ(at(0, 0), 10);
  EXPECT_EQ(at(2, 0), 20);
  EXPECT_EQ(at(5, 2), 30);
  EXPECT_EQ(at(0, 3), 40);
  EXPECT_EQ(at(3, 5), 50);
  EXPECT_EQ(at(4, 3), 0);  // past the last frame
}

}  // namespace
}  // namespace lp

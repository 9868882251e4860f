// Readers on the real maps, PFM orientation and byte order, writers round-trip, limits and bad data.
#include "engine/image/image_io.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <bit>
#include <cmath>
#include <cstring>

#include "engine/core/error.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

Image read_real(const std::string& file) {
  return read_image_file(test::envmap_path(file)).image;
}

// A 3x2 image whose every value is distinct: (x, y, c) -> 100 y + 10 x + c.
Image numbered_image() {
  Image img(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      const float base = float(100 * y + 10 * x);
      img.set(x, y, {base, base + 1, base + 2});
    }
  return img;
}

std::vector<uint8_t> pfm_bytes(const std::string& header, const std::vector<float>& values,
                               bool little_endian) {
  std::vector<uint8_t> out(header.begin(), header.end());
  for (float v : values) {
    uint32_t bits = std::bit_cast<uint32_t>(v);
    if (!little_endian) bits = __builtin_bswap32(bits);
    const auto* b = reinterpret_cast<const uint8_t*>(&bits);
    out.insert(out.end(), b, b + 4);
  }
  return out;
}

void expect_error_kind(ErrorKind kind, const std::function<void()>& f) {
  try {
    f();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
  }
}

TEST(ImageIo, RealMapsLoadAtTheirSize) {
  for (const auto& file : test::real_envmap_files()) {
    const DecodedImage d = read_image_file(test::envmap_path(file));
    EXPECT_EQ(d.image.width(), test::kRealMapWidth) << file;
    EXPECT_EQ(d.image.height(), test::kRealMapHeight) << file;
    EXPECT_EQ(enum_name(d.format), file.substr(file.size() - 3)) << file;
    for (float v : d.image.data()) ASSERT_TRUE(std::isfinite(v)) << file;
  }
}

TEST(ImageIo, ExrAndPfmOfTheSameSceneAreIdentical) {
  const Image exr = read_real("forest.exr"), pfm = read_real("forest.pfm");
  ASSERT_EQ(exr.data().size(), pfm.data().size());
  for (size_t i = 0; i < exr.data().size(); ++i) ASSERT_EQ(exr.data()[i], pfm.data()[i]) << "value " << i;
}

TEST(ImageIo, ExrAndRadianceHdrOfTheSameSceneAgreeToRgbePrecision) {
  const Image exr = read_real("studio.exr"), hdr = read_real("studio.hdr");
  ASSERT_EQ(exr.data().size(), hdr.data().size());
  // RGBE keeps 8 mantissa bits relative to the pixel's largest channel; the absolute floor (0.4%
  // of the map's mean, 0.26) covers lossy-codec noise in near-black pixels.
  double abs_error = 0, abs_value = 0;
  for (int y = 0; y < exr.height(); ++y)
    for (int x = 0; x < exr.width(); ++x) {
      const Rgb a = exr.at(x, y), b = hdr.at(x, y);
      const float tol = std::max(max_component(a), max_component(b)) * (1.0f / 128.0f) + 1e-3f;
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(a[c], b[c], tol) << x << "," << y;
        abs_error += std::abs(a[c] - b[c]);
        abs_value += a[c];
      }
    }
  EXPECT_LT(abs_error / abs_value,
            1.0 / 256);  // under one step of an 8-bit mantissa on average (measured 0.24%)
}

TEST(ImageIo, PfmRowsAreStoredBottomToTop) {
  // Stored rows: first the bottom row (y = 1), then the top row (y = 0).
  const auto bytes = pfm_bytes("PF\n1 2\n-1.0\n", {1, 2, 3, 4, 5, 6}, true);
  const Image img = read_image(bytes).image;
  EXPECT_EQ(img.at(0, 0), (Rgb{4, 5, 6}));
  EXPECT_EQ(img.at(0, 1), (Rgb{1, 2, 3}));
}

TEST(ImageIo, PfmByteOrderFollowsTheSignOfTheScale) {
  const std::vector<float> values = {0.5f, 1.5f, 2.5f};
  EXPECT_EQ(read_image(pfm_bytes("PF\n1 1\n-1.0\n", values, true)).image.at(0, 0), (Rgb{0.5f, 1.5f, 2.5f}));
  EXPECT_EQ(read_image(pfm_bytes("PF\n1 1\n1.0\n", values, false)).image.at(0, 0), (Rgb{0.5f, 1.5f, 2.5f}));
}

TEST(ImageIo, GreyPfmFillsAllChannels) {
  const Image img = read_image(pfm_bytes("Pf\n2 1\n-1\n", {3.0f, 7.0f}, true)).image;
  EXPECT_EQ(img.at(0, 0), (Rgb{3, 3, 3}));
  EXPECT_EQ(img.at(1, 0), (Rgb{7, 7, 7}));
}

TEST(ImageIo, ExrRoundTripIsExact) {
  const Image src = numbered_image();
  const Image back = read_image(write_exr(src)).image;
  ASSERT_EQ(back.width(), 3);
  ASSERT_EQ(back.height(), 2);
  for (size_t i = 0; i < src.data().size(); ++i) EXPECT_EQ(src.data()[i], back.data()[i]);
}

// Half precision keeps 11 significant bits: a relative error of at most 2^-11 (every value here is normal).
TEST(ImageIo, ExrInHalfPrecisionRoundsEachValueToTheNearestHalf) {
  const Image src = read_real("forest.exr");
  const Image back = read_image(write_exr(src, ExrCompression::Zip, PixelPrecision::Half)).image;
  ASSERT_EQ(back.width(), src.width());
  for (size_t i = 0; i < src.data().size(); ++i)
    ASSERT_NEAR(back.data()[i], src.data()[i], std::ldexp(src.data()[i], -11) + 1e-7f) << "value " << i;
}

TEST(ImageIo, PfmRoundTripIsExact) {
  const Image src = read_real("forest.pfm");
  const Image back = read_image(write_pfm(src)).image;
  ASSERT_EQ(std::memcmp(src.data().data(), back.data().data(), src.data().size() * 4), 0);
}

TEST(ImageIo, HdrRoundTripKeepsRgbePrecision) {
  const Image src = numbered_image();
  const Image back = read_image(write_hdr(src)).image;
  for (size_t i = 0; i < src.data().size(); ++i)
    EXPECT_NEAR(src.data()[i], back.data()[i], src.data()[i] / 128.0f + 1e-3f);
}

TEST(ImageIo, PngIsToneMappedWithExposureAndGamma) {
  Image src(2, 1);
  src.set(0, 0, {0.5f, 0.25f, 0.0f});
  src.set(1, 0, {4.0f, 0.0f, 0.0f});
  auto decode = [](const std::vector<uint8_t>& png) {
    int w = 0, h = 0, n = 0;
    unsigned char* p = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &n, 3);
    std::vector<int> out(p, p + w * h * 3);
    stbi_image_free(p);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 1);
    return out;
  };
  const auto srgb = decode(write_png(src));
  EXPECT_EQ(srgb[0], 188);  // sRGB(0.5) = 0.7354
  EXPECT_EQ(srgb[1], 137);  // sRGB(0.25) = 0.5371
  EXPECT_EQ(srgb[3], 255);  // clipped
  const auto gamma2 = decode(write_png(src, {.exposure = -1.0f, .gamma = 2.0f}));
  EXPECT_EQ(gamma2[0], 128);  // (0.5 * 2^-1)^(1/2) = 0.5
  EXPECT_EQ(gamma2[3], 255);  // 4 * 0.5 = 2, clipped
}

TEST(ImageIo, SizeLimitIsCheckedBeforeAllocating) {
  const std::string header = "PF\n100000 100000\n-1.0\n";
  const std::vector<uint8_t> bytes(header.begin(), header.end());
  expect_error_kind(ErrorKind::TooLarge, [&] { read_image(bytes); });
  ImageLimits small;
  small.max_pixels = 1000;
  expect_error_kind(ErrorKind::TooLarge, [&] { read_image_file(test::envmap_path("forest.exr"), small); });
  expect_error_kind(ErrorKind::TooLarge, [&] { read_image_file(test::envmap_path("studio.hdr"), small); });
  expect_error_kind(ErrorKind::TooLarge, [&] { read_image_file(test::envmap_path("forest.pfm"), small); });
}

TEST(ImageIo, TruncatedFilesAreCorrupt) {
  for (const std::string file : {"forest.exr", "forest.pfm", "studio.hdr"}) {
    auto bytes = test::read_bytes(test::envmap_path(file));
    bytes.resize(bytes.size() / 2);
    expect_error_kind(ErrorKind::Corrupt, [&] { read_image(bytes); });
  }
  const std::string bad_header = "PF\nabc 2\n-1.0\n";
  expect_error_kind(ErrorKind::Corrupt,
                    [&] { read_image(std::vector<uint8_t>(bad_header.begin(), bad_header.end())); });
}

TEST(ImageIo, UnknownBytesAreUnsupported) {
  const std::string text = "hello, this is not an image";
  expect_error_kind(ErrorKind::Unsupported,
                    [&] { read_image(std::vector<uint8_t>(text.begin(), text.end())); });
  expect_error_kind(ErrorKind::Unsupported, [&] { read_image(std::vector<uint8_t>{}); });
}

TEST(ImageIo, PixelValuesComeBackAsStored) {
  const auto bytes = pfm_bytes("PF\n2 1\n-1.0\n", {1, NAN, 1, 1, -0.5f, INFINITY}, true);
  const Image img = read_image(bytes).image;
  EXPECT_TRUE(std::isnan(img.at(0, 0).y));
  EXPECT_EQ(img.at(1, 0).y, -0.5f);
  EXPECT_EQ(img.at(1, 0).z, INFINITY);
}

TEST(ImageIo, FormatIsDetectedFromMagicBytesNotNames) {
  EXPECT_EQ(detect_format(test::read_bytes(test::envmap_path("forest.exr"))), ImageFormat::Exr);
  EXPECT_EQ(detect_format(test::read_bytes(test::envmap_path("forest.pfm"))), ImageFormat::Pfm);
  EXPECT_EQ(detect_format(test::read_bytes(test::envmap_path("studio.hdr"))), ImageFormat::Hdr);
}

}  // namespace
}  // namespace lp

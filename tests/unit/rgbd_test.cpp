// RGBD as Babylon.js encodes it (toRGBD) and decodes it (fromRGBD): hand-computed bytes, the round trip
// within the 8-bit precision the format has, saturation above its range, and whole images.
#include "engine/image/rgbd.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/image.hpp"

namespace lp {
namespace {

TEST(Rgbd, EncodesAsBabylonsShader) {
  // (0.5, 0.25, 0): D = min(floor(255 / 0.5), 255) / 255 = 1, so rgb = round(255 (0.5, 0.25, 0)^(1 / 2.2)).
  EXPECT_EQ(encode_rgbd({0.5f, 0.25f, 0.0f}), (Rgbd8{186, 136, 0, 255}));
  // (10, 5, 1): D = floor(25.5) / 255 = 25 / 255, colour D = (0.98, 0.49, 0.098).
  EXPECT_EQ(encode_rgbd({10.0f, 5.0f, 1.0f}), (Rgbd8{253, 184, 89, 25}));
  // Black, negative and NaN channels: D = 1.
  EXPECT_EQ(encode_rgbd({0.0f, -1.0f, NAN}), (Rgbd8{0, 0, 0, 255}));
  // 1000 saturates at the range: D = 1 / 255, rgb = 1.
  EXPECT_EQ(encode_rgbd({1000.0f, 0.0f, 0.0f}), (Rgbd8{255, 0, 0, 1}));
}

TEST(Rgbd, DecodesAsBabylonsShader) {
  const Rgb c = decode_rgbd({253, 184, 89, 25});
  EXPECT_NEAR(c.x, std::pow(253 / 255.0, 2.2) * 255 / 25, 1e-5);
  EXPECT_NEAR(c.y, std::pow(184 / 255.0, 2.2) * 255 / 25, 1e-5);
  EXPECT_NEAR(c.z, std::pow(89 / 255.0, 2.2) * 255 / 25, 1e-5);
}

TEST(Rgbd, RoundTripKeepsEightBitsAfterTheGammaCurve) {
  // From 1 to the range, D (whole 255ths) keeps the brightest channel in (0.5, 1] before the 1/2.2
  // power: its byte is at least 187, so half a step is under 2.2 * 0.5 / 187 < 0.6% of it. Below 1, D = 1 and
  // the format is plain 8-bit gamma 2.2: half a step is 2.2 * 0.5 / (255 v^(1 / 2.2)) of v.
  for (double v = 1e-2; v <= 255; v *= 1.07) {
    const float f = float(v);
    const Rgb back = decode_rgbd(encode_rgbd({f, f * 0.5f, f * 0.1f}));
    const double tolerance = v >= 1 ? 6e-3 : 1.1 / (255 * std::pow(v, 1 / 2.2)) + 1e-5;
    EXPECT_NEAR(back.x / f, 1.0, tolerance) << v;
  }
  EXPECT_FLOAT_EQ(decode_rgbd(encode_rgbd({5000.0f, 0.0f, 0.0f})).x, 255.0f);
}

TEST(Rgbd, ImagesRoundTripPixelByPixel) {
  Image image(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) image.set(x, y, {float(x + 1), float(y) * 0.3f, 0.02f * float(x * y + 1)});
  const auto bytes = encode_rgbd_pixels(image);
  ASSERT_EQ(bytes.size(), 3u * 2 * 4);
  EXPECT_EQ((Rgbd8{bytes[4 * 4], bytes[4 * 4 + 1], bytes[4 * 4 + 2], bytes[4 * 4 + 3]}),
            encode_rgbd(image.at(1, 1)));
  const Image back = decode_rgbd_pixels(bytes, 3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_NEAR(back.at(x, y).x / image.at(x, y).x, 1.0, 6e-3);  // x >= 1
  EXPECT_THROW(decode_rgbd_pixels(bytes, 2, 2), Error);
}

}  // namespace
}  // namespace lp

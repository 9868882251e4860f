// OIDN's input transforms: the PU curve normalised so that 65504 maps to 1, the sRGB curve, both inverted
// exactly enough, and the autoexposure's key over the geometric mean of 16x16 bins.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/denoise/transfer.hpp"
#include "support/constant_map.hpp"

namespace lp::denoise {
namespace {

TEST(DenoiseTransfer, PuSpansHalfFloatRangeAndInverts) {
  EXPECT_NEAR(transfer_forward(Transfer::Pu, 65504.f), 1.f, 1e-6f);
  EXPECT_EQ(transfer_forward(Transfer::Pu, 0.f), 0.f);
  float previous = 0;
  for (float y = 1e-7f; y < 65504.f; y *= 1.37f) {
    const float x = transfer_forward(Transfer::Pu, y);
    EXPECT_GT(x, previous) << y;  // increasing across its three pieces
    previous = x;
    EXPECT_NEAR(transfer_inverse(Transfer::Pu, x), y, 2e-5f * y + 1e-12f) << y;
  }
  // Above y1 the curve is e log(y + f) + g (OIDN's constants), over its value at 65504.
  EXPECT_NEAR(transfer_forward(Transfer::Pu, 1.f),
              (0.192653254f * std::log(1.00626026f) + 0.998620152f) /
                  (0.192653254f * std::log(65504.00626f) + 0.998620152f),
              1e-6f);
}

TEST(DenoiseTransfer, SrgbCurve) {
  EXPECT_NEAR(transfer_forward(Transfer::Srgb, 0.0031308f), 0.04045f, 1e-6f);
  EXPECT_NEAR(transfer_forward(Transfer::Srgb, 1.f), 1.f, 1e-6f);
  EXPECT_NEAR(transfer_forward(Transfer::Srgb, 0.5f), 0.735357f, 1e-5f);
  for (float y = 0; y <= 1; y += 0.01f)
    EXPECT_NEAR(transfer_inverse(Transfer::Srgb, transfer_forward(Transfer::Srgb, y)), y, 1e-6f);
}

TEST(DenoiseTransfer, AutoexposureIsKeyOverGeometricMean) {
  // Luminance 0.212671 r + 0.715160 g + 0.072169 b.
  EXPECT_NEAR(autoexposure(test::constant_image(40, 30, {2, 2, 2})), 0.18f / 2, 1e-6f);
  // Two halves of luminance 1 and 4, on bin borders: the geometric mean is 2.
  Image halves = test::constant_image(64, 32, {1, 1, 1});
  for (int y = 0; y < 32; ++y)
    for (int x = 32; x < 64; ++x) halves.set(x, y, {4, 4, 4});
  EXPECT_NEAR(autoexposure(halves), 0.18f / 2, 1e-6f);
  EXPECT_EQ(autoexposure(test::constant_image(8, 8, {0, 0, 0})), 1.f);
}

}  // namespace
}  // namespace lp::denoise

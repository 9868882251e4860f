// The tone curves against their references: Khronos PBR Neutral against the values its reference code
// (KhronosGroup/ToneMapping, PBR_Neutral/lut-writer.mjs, run under node) gives, with its published
// inverse; AgX and ACES against an independent double-precision port of three.js's shaders; every curve
// monotonic; and the 8-bit output of an 18% grey card per curve.
#include "engine/image/tonemap.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "engine/image/image_io.hpp"
#include "engine/image/tone/curves.hpp"

namespace lp {
namespace {

struct Reference {
  Vec3 in, out;
};

void expect_near(Vec3 got, Vec3 want, float tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

// pbrNeutral() of the reference code, printed to 9 decimals. The start of compression is a peak (after
// the 0.04 offset) of 0.76; the toe is a least channel below 0.08.
const std::vector<Reference> kNeutralReference = {
    {{0.05f, 0.05f, 0.05f}, {0.015625f, 0.015625f, 0.015625f}},    // toe, grey
    {{0.02f, 0.3f, 0.6f}, {0.0025f, 0.2825f, 0.5825f}},            // toe, colour
    {{0.07f, 0.5f, 0.75f}, {0.030625f, 0.460625f, 0.710625f}},     // toe, below compression
    {{0.1f, 0.5f, 0.8f}, {0.06f, 0.46f, 0.76f}},                   // exactly at the start
    {{0.3f, 0.5f, 0.79f}, {0.26f, 0.46f, 0.75f}},                  // just below
    {{0.3f, 0.5f, 0.81f}, {0.259895517f, 0.459779628f, 0.7696f}},  // just above
    {{0.9f, 0.5f, 0.2f}, {0.830588235f, 0.445964993f, 0.157497561f}},
    {{2.0f, 1.0f, 0.5f}, {0.96f, 0.534090506f, 0.321135759f}},
    {{0.18f, 0.18f, 0.18f}, {0.14f, 0.14f, 0.14f}},
    {{1.0f, 1.0f, 1.0f}, {0.869090909f, 0.869090909f, 0.869090909f}},
    {{10.0f, 10.0f, 10.0f}, {0.993898305f, 0.993898305f, 0.993898305f}},
};

TEST(ToneMap, PbrNeutralMatchesTheKhronosReferenceCode) {
  for (const Reference& r : kNeutralReference) {
    SCOPED_TRACE(testing::Message() << r.in.x << " " << r.in.y << " " << r.in.z);
    expect_near(tone::pbr_neutral(r.in), r.out, 2e-6f);
  }
}

TEST(ToneMap, PbrNeutralPublishedInverseRoundTrips) {
  for (const Reference& r : kNeutralReference) {
    SCOPED_TRACE(testing::Message() << r.in.x << " " << r.in.y << " " << r.in.z);
    // The inverse of the reference outputs gives the inputs back (relative error 1e-5 in float).
    const Vec3 back = tone::pbr_neutral_inverse(r.out);
    expect_near(back, r.in, 1e-5f * std::max(1.0f, r.in.x));
  }
  for (float v = 0.001f; v < 50.0f; v *= 1.1f) {
    const Vec3 c{v, 0.5f * v, 0.25f * v};
    const Vec3 back = tone::pbr_neutral_inverse(tone::pbr_neutral(c));
    expect_near(back, c, 2e-4f * v + 1e-6f);
  }
}

// three.js AgXToneMapping and ACESFilmicToneMapping ported to JavaScript doubles (GLSL's column-major
// matrices, inverses computed in double), before clipping.
TEST(ToneMap, AgxAndAcesMatchThreeJs) {
  expect_near(tone::agx({0.18f, 0.18f, 0.18f}), {0.2145243f, 0.2145204f, 0.2145145f}, 2e-5f);
  expect_near(tone::agx({0.5f, 0.2f, 0.05f}), {0.4447984f, 0.2330776f, 0.1010596f}, 2e-5f);
  expect_near(tone::agx({4, 2, 1}), {0.8833590f, 0.7449561f, 0.6327987f}, 2e-5f);
  expect_near(tone::agx({0.01f, 0.02f, 0.03f}), {0.0058630f, 0.0192747f, 0.0327272f}, 2e-5f);
  expect_near(tone::aces_hill({0.18f, 0.18f, 0.18f}), {0.2131054f, 0.2131054f, 0.2131033f}, 2e-6f);
  expect_near(tone::aces_hill({0.5f, 0.2f, 0.05f}), {0.5752044f, 0.2544459f, 0.0547926f}, 2e-6f);
  expect_near(tone::aces_hill({4, 2, 1}), {0.9647061f, 0.8922991f, 0.7998549f}, 2e-6f);
  expect_near(tone::aces_hill({0.01f, 0.02f, 0.03f}), {0.0024232f, 0.0071362f, 0.0129179f}, 2e-6f);
}

const ToneCurve kCurves[] = {ToneCurve::Standard, ToneCurve::Neutral, ToneCurve::Agx, ToneCurve::Aces,
                             ToneCurve::Reinhard};

// On a grey ramp from 1e-4 to 1e4 and on an orange one, in steps of 0.2%, no channel decreases and the
// output stays in [0, 1]. One exception of the reference formulation itself: AgX's outset matrix mixes
// the channels, and on a coloured ramp where the brightest channel saturates (near 26 and 47 on this
// ramp) a channel dips by up to 1.9e-4 before clipping and 2.1e-5 after (the double-precision port of
// three.js's shader shows the same), less than a hundredth of an 8-bit step.
TEST(ToneMap, EveryCurveIsMonotonicOnADenseRamp) {
  for (const ToneCurve curve : kCurves) {
    for (const Vec3 tint : {Vec3{1, 1, 1}, Vec3{1.0f, 0.6f, 0.2f}}) {
      SCOPED_TRACE(testing::Message() << enum_name(curve) << " tint " << tint.y);
      const float slack = curve == ToneCurve::Agx && tint.y != 1.0f ? 3e-5f : 1e-6f;
      Vec3 last = apply_tone_curve(curve, {0, 0, 0});
      int steps = 0;
      for (float v = 1e-4f; v < 1e4f; v *= 1.002f, ++steps) {
        const Vec3 out = apply_tone_curve(curve, tint * v);
        ASSERT_GE(out.x, last.x - slack) << "at " << v;
        ASSERT_GE(out.y, last.y - slack) << "at " << v;
        ASSERT_GE(out.z, last.z - slack) << "at " << v;
        ASSERT_GE(std::min({out.x, out.y, out.z}), 0.0f) << "at " << v;
        ASSERT_LE(std::max({out.x, out.y, out.z}), 1.0f) << "at " << v;
        last = out;
      }
      EXPECT_EQ(steps, 9220);
      EXPECT_GT(std::max({last.x, last.y, last.z}), 0.99f);  // the top of the ramp is (nearly) white
    }
  }
}

uint8_t grey_card(ToneCurve curve, std::optional<float> gamma = std::nullopt) {
  const ToneMapper map({.exposure = 0.0f, .gamma = gamma, .curve = curve});
  const float card[3] = {0.18f, 0.18f, 0.18f};
  uint8_t out[3];
  map(card, out);
  EXPECT_EQ(out[0], out[1]);
  EXPECT_EQ(out[1], out[2]);
  return out[0];
}

// An 18% grey card in sRGB 8-bit: standard round(255 * srgb(0.18)) = round(117.69); neutral 0.18 - 0.04
// = 0.14, round(104.56); agx 0.21452, round(128.2); aces 0.21311, round(127.25); reinhard 0.18 / 1.18
// = 0.15254, round(108.86).
TEST(ToneMap, EighteenPercentGreyCardPerCurve) {
  EXPECT_EQ(grey_card(ToneCurve::Standard), 118);
  EXPECT_EQ(grey_card(ToneCurve::Neutral), 105);
  EXPECT_EQ(grey_card(ToneCurve::Agx), 128);
  EXPECT_EQ(grey_card(ToneCurve::Aces), 127);
  EXPECT_EQ(grey_card(ToneCurve::Reinhard), 109);
  // With gamma 2.2 instead of the sRGB curve: neutral 0.14^(1/2.2) = 0.40889, round(104.27).
  EXPECT_EQ(grey_card(ToneCurve::Neutral, 2.2f), 104);
}

TEST(ToneMap, NanNegativeAndHugeValuesAreBlackOrWhite) {
  for (const ToneCurve curve : kCurves) {
    SCOPED_TRACE(enum_name(curve));
    const ToneMapper map({.exposure = 0.0f, .gamma = std::nullopt, .curve = curve});
    const float bad[3] = {std::nanf(""), -5.0f, 1e30f};
    uint8_t out[3];
    map(bad, out);
    EXPECT_LE(out[0], out[2]);
    EXPECT_EQ(out[2], 255);
    const float black[3] = {std::nanf(""), -5.0f, 0.0f};
    map(black, out);
    EXPECT_EQ(out[0], 0);
    EXPECT_EQ(out[1], 0);
    EXPECT_EQ(out[2], 0);
  }
}

// The table lookup rounds as lround(255 * encode(x)) does, at every code: on an even ramp and on a
// geometric one down to 1e-9; also for a gamma far from the sRGB curve's (0.2: many codes per bin).
TEST(ToneMap, DisplayEncodingRoundsToTheNearestCode) {
  const ToneMapper srgb({}), gamma2({.gamma = 2.0f}), gamma02({.gamma = 0.2f});
  std::vector<float> ramp;
  for (int i = 0; i <= 4000; ++i) ramp.push_back(float(i) / 4000.0f);
  for (float x = 1e-9f; x < 1.0f; x *= 1.01f) ramp.push_back(x);
  for (const float x : ramp) {
    const float px[3] = {x, x, x};
    uint8_t out[3];
    srgb(px, out);
    const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(double(x), 1 / 2.4) - 0.055;
    EXPECT_NEAR(out[0], s * 255.0, 0.5 + 1e-4) << x;
    gamma2(px, out);
    EXPECT_NEAR(out[0], std::sqrt(double(x)) * 255.0, 0.5 + 1e-4) << x;
    gamma02(px, out);
    EXPECT_NEAR(out[0], std::pow(double(x), 5.0) * 255.0, 0.5 + 1e-4) << x;
  }
}

}  // namespace
}  // namespace lp

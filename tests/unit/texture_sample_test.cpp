// Texture lookups: wrap modes, bilinear and trilinear filtering, KHR_texture_transform, decoding with
// the sRGB curve or linearly, size limits before decoding, and the shared cache.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/image_io.hpp"
#include "engine/texture/srgb.hpp"
#include "engine/texture/texture_cache.hpp"
#include "engine/texture/texture_decode.hpp"
#include "engine/texture/texture_transform.hpp"

namespace lp {
namespace {

// 4 x 1 texels of values 0, 1, 2, 3 in every channel.
Texture ramp() {
  std::vector<float> t;
  for (int x = 0; x < 4; ++x) t.insert(t.end(), {float(x), float(x), float(x)});
  return Texture(4, 1, 3, t);
}

TEST(WrapMode, TexelIndicesOutsideTheImage) {
  EXPECT_EQ(wrap_texel(-1, 4, WrapMode::Repeat), 3);
  EXPECT_EQ(wrap_texel(5, 4, WrapMode::Repeat), 1);
  EXPECT_EQ(wrap_texel(-1, 4, WrapMode::ClampToEdge), 0);
  EXPECT_EQ(wrap_texel(9, 4, WrapMode::ClampToEdge), 3);
  EXPECT_EQ(wrap_texel(4, 4, WrapMode::MirroredRepeat), 3);
  EXPECT_EQ(wrap_texel(-1, 4, WrapMode::MirroredRepeat), 0);
  EXPECT_EQ(wrap_texel(8, 4, WrapMode::MirroredRepeat), 0);
}

TEST(TextureSample, TexelCentresReturnTheTexelAndMidpointsTheAverage) {
  const Texture t = ramp();
  for (int x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(t.sample_bilinear({(float(x) + 0.5f) / 4, 0.5f}).r, float(x));
  EXPECT_FLOAT_EQ(t.sample_bilinear({0.5f, 0.5f}).r, 1.5f);
}

TEST(TextureSample, WrapModesAtTheLeftEdge) {
  const Texture t = ramp();
  const Point2 edge{0.0f, 0.5f};  // halfway between texel 0 and the texel left of it
  EXPECT_FLOAT_EQ(t.sample_bilinear(edge, {WrapMode::Repeat, WrapMode::Repeat}).r, 1.5f);  // (0 + 3) / 2
  EXPECT_FLOAT_EQ(t.sample_bilinear(edge, {WrapMode::ClampToEdge, WrapMode::Repeat}).r, 0.0f);
  EXPECT_FLOAT_EQ(t.sample_bilinear(edge, {WrapMode::MirroredRepeat, WrapMode::Repeat}).r, 0.0f);
  // Far outside: repeat shifts by whole periods, mirrored repeat reflects every other period.
  EXPECT_FLOAT_EQ(t.sample_bilinear({7.125f, 0.5f}, {WrapMode::Repeat, WrapMode::Repeat}).r, 0.0f);
  EXPECT_FLOAT_EQ(t.sample_bilinear({-0.125f, 0.5f}, {WrapMode::MirroredRepeat, WrapMode::Repeat}).r, 0.0f);
  EXPECT_FLOAT_EQ(t.sample_bilinear({1.875f, 0.5f}, {WrapMode::MirroredRepeat, WrapMode::Repeat}).r, 0.0f);
  EXPECT_FLOAT_EQ(t.sample_bilinear({1e30f, 0.5f}, {WrapMode::ClampToEdge, WrapMode::Repeat}).r, 3.0f);
  EXPECT_TRUE(std::isfinite(t.sample_bilinear({std::nanf(""), 0.5f}).r));
}

TEST(TextureSample, TrilinearBlendsTheLevelsAroundAFractionalLevel) {
  const Texture t = ramp();  // level 1: 2 x 1 of 0.5, 2.5; level 2: 1 x 1 of 1.5
  const Point2 uv{0.25f, 0.5f};
  EXPECT_FLOAT_EQ(t.sample(uv, 1.0f).r, 0.5f);
  EXPECT_FLOAT_EQ(t.sample(uv, 2.0f).r, 1.5f);
  EXPECT_FLOAT_EQ(t.sample(uv, 1.25f).r, 0.75f * 0.5f + 0.25f * 1.5f);
  EXPECT_FLOAT_EQ(t.sample(uv, 9.0f).r, 1.5f);  // clamped to the last level
  EXPECT_FLOAT_EQ(t.sample(uv, -3.0f).r, t.sample_bilinear(uv).r);
}

TEST(TextureTransform, ScaleThenRotateThenOffset) {
  TextureTransform t;
  t.offset = {0.5f, 0.25f};
  t.scale = {2.0f, 3.0f};
  t.rotation = float(M_PI) / 2;
  // (1, 1) scaled to (2, 3), rotated a quarter turn (u' = v, v' = -u) to (3, -2), offset to (3.5, -1.75).
  const Point2 uv = t.apply({1.0f, 1.0f});
  EXPECT_NEAR(uv.x, 3.5f, 1e-6f);
  EXPECT_NEAR(uv.y, -1.75f, 1e-6f);
  EXPECT_TRUE(TextureTransform{}.identity());
}

TEST(TextureTransform, TheExtensionsExampleReadsTheLowerLeftQuadrant) {
  // KHR_texture_transform's example: offset (0, 1), rotation pi/2, scale 0.5 "utilizes only the lower
  // left quadrant of the source image" (u in [0, 0.5], v in [0.5, 1], v down the image).
  TextureTransform t;
  t.offset = {0.0f, 1.0f};
  t.rotation = float(M_PI) / 2;
  t.scale = {0.5f, 0.5f};
  const std::pair<Point2, Point2> corners[] = {
      {{0, 0}, {0, 1}}, {{1, 0}, {0, 0.5f}}, {{0, 1}, {0.5f, 1}}, {{1, 1}, {0.5f, 0.5f}}};
  for (const auto& [in, out] : corners) {
    const Point2 uv = t.apply(in);
    EXPECT_NEAR(uv.x, out.x, 1e-6f) << in.x << ", " << in.y;
    EXPECT_NEAR(uv.y, out.y, 1e-6f) << in.x << ", " << in.y;
  }
}

std::vector<uint8_t> png_bytes(int w, int h, int channels, const std::vector<uint8_t>& pixels) {
  std::vector<uint8_t> out;
  stbi_write_png_to_func(
      [](void* ctx, void* data, int size) {
        auto* o = static_cast<std::vector<uint8_t>*>(ctx);
        o->insert(o->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
      },
      &out, w, h, channels, pixels.data(), w * channels);
  return out;
}

TEST(TextureDecode, ColourTexturesAreDecodedFromSrgbAndDataTexturesKeptLinear) {
  const auto png = png_bytes(1, 1, 4, {128, 255, 0, 64});
  const Texture colour = decode_texture(png, ColorSpace::Srgb, {}, "t.png");
  const Texture data = decode_texture(png, ColorSpace::Linear, {}, "t.png");
  ASSERT_EQ(colour.channels(), 4);
  EXPECT_NEAR(colour.texel(0, 0, 0).r, 0.2158605f, 1e-6f);  // sRGB 128/255
  EXPECT_FLOAT_EQ(colour.texel(0, 0, 0).g, 1.0f);
  EXPECT_FLOAT_EQ(colour.texel(0, 0, 0).a, 64 / 255.0f);  // alpha is never sRGB
  EXPECT_FLOAT_EQ(data.texel(0, 0, 0).r, 128 / 255.0f);
  EXPECT_EQ(decode_texture(png_bytes(2, 1, 3, {1, 2, 3, 4, 5, 6}), ColorSpace::Srgb, {}, "t.png").channels(),
            3);
}

// Large enough that the samples are converted in several stretches, each releasing the file's decoded
// pages behind it: every texel keeps its value.
TEST(TextureDecode, EveryTexelOfALargeTextureKeepsItsValue) {
  const int w = 600, h = 300;
  std::vector<uint8_t> pixels(size_t(w) * h * 4);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t((i * 7 + i / 4093) % 256);
  const auto png = png_bytes(w, h, 4, pixels);
  const Texture t = decode_texture(png, ColorSpace::Srgb, {}, "t.png");
  ASSERT_EQ(t.channels(), 4);
  size_t wrong = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = &pixels[(size_t(y) * w + size_t(x)) * 4];
      const Rgba v = t.texel(0, x, y);
      wrong += v.r != srgb_to_linear(p[0] / 255.0f) || v.b != srgb_to_linear(p[2] / 255.0f) ||
               v.a != p[3] / 255.0f;
    }
  EXPECT_EQ(wrong, 0u);
  // What decoding may hold at most: the texture as it is kept, and the decoder's 8-bit buffer.
  EXPECT_EQ(mip_pyramid_bytes(w, h, 4), t.memory_bytes());
  EXPECT_EQ(texture_decode_bytes(png, w, h), t.memory_bytes() + int64_t(w) * h * 4);
}

TEST(TextureDecode, FloatFormatsAreLinearInBothSpaces) {
  Image image(2, 1);
  image.set(0, 0, {0.25f, 2.0f, 8.0f});
  for (const auto& bytes : {write_exr(image), write_hdr(image)}) {
    const Texture t = decode_texture(bytes, ColorSpace::Srgb, {}, "t");
    EXPECT_FLOAT_EQ(t.texel(0, 0, 0).r, 0.25f);
    EXPECT_FLOAT_EQ(t.texel(0, 0, 0).b, 8.0f);
  }
}

TEST(TextureDecode, SizeIsCheckedBeforeDecodingAndGarbageIsRefused) {
  ImageLimits limits;
  limits.max_pixels = 3;
  try {
    decode_texture(png_bytes(2, 2, 3, std::vector<uint8_t>(12, 7)), ColorSpace::Srgb, limits, "big.png");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::TooLarge);
  }
  const std::vector<uint8_t> garbage{'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'};
  EXPECT_THROW(decode_texture(garbage, ColorSpace::Srgb, {}, "x"), Error);
  auto truncated = png_bytes(4, 4, 3, std::vector<uint8_t>(48, 9));
  truncated.resize(truncated.size() / 2);
  EXPECT_THROW(decode_texture(truncated, ColorSpace::Srgb, {}, "x"), Error);
}

TEST(TextureCache, SharesOneTexturePerKeyAndSpaceWhileItIsHeld) {
  TextureCache cache;
  int decodes = 0;
  const auto decode = [&] {
    ++decodes;
    return ramp();
  };
  auto a = cache.get("ramp", ColorSpace::Srgb, decode);
  auto b = cache.get("ramp", ColorSpace::Srgb, decode);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(decodes, 1);
  auto c = cache.get("ramp", ColorSpace::Linear, decode);
  EXPECT_NE(a.get(), c.get());
  EXPECT_EQ(cache.size(), 2u);
  a.reset(), b.reset(), c.reset();
  EXPECT_EQ(cache.size(), 0u);  // released with its last user
  cache.get("ramp", ColorSpace::Srgb, decode);
  EXPECT_EQ(decodes, 3);
}

TEST(Srgb, TransferFunctionEndsAndKnee) {
  EXPECT_FLOAT_EQ(srgb_to_linear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgb_to_linear(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgb_to_linear(0.04045f), 0.04045f / 12.92f);
}

}  // namespace
}  // namespace lp

// The denoiser on generated images with the vendored weights: tiles give the whole-image result, a flat
// image stays flat, noise on a smooth image goes (relMSE against the clean image), and bad inputs are
// refused with DenoiseError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "engine/denoise/denoiser.hpp"
#include "engine/denoise/tiles.hpp"

namespace lp::denoise {
namespace {

Image smooth(int width, int height) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.set(x, y,
              {0.2f + 0.6f * float(x) / float(width), 0.3f + 0.4f * float(y) / float(height),
               0.5f + 0.3f * std::sin(float(x) / 40.f)});
  return img;
}

// Each channel times an exponential variate (mean 1): the spread of a few samples per pixel.
Image noisy(const Image& clean, unsigned seed) {
  std::mt19937 rng(seed);
  std::exponential_distribution<float> spread(1.f);
  Image img = clean;
  for (float& v : img.data()) v *= spread(rng);
  return img;
}

Image filled(int width, int height, Rgb c) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) img.set(x, y, c);
  return img;
}

double rel_mse(const Image& a, const Image& reference) {
  double sum = 0;
  for (size_t i = 0; i < a.data().size(); ++i) {
    const double r = reference.data()[i], d = a.data()[i] - r;
    sum += d * d / (r * r + 1e-2);
  }
  return sum / double(a.data().size());
}

const Denoiser& denoiser() {
  static const Denoiser d;
  return d;
}

TEST(Denoise, VendoredWeightsAreAvailable) {
  EXPECT_TRUE(denoiser().available()) << denoiser().weights_dir();
  EXPECT_FALSE(Denoiser("/nonexistent").available());
}

TEST(Denoise, TilePlanCoversTheImageWithAlignedOverlaps) {
  const auto tiles = plan_tiles(300, 200, kMinTileSize);
  EXPECT_GT(tiles.size(), 4u);
  std::vector<int> covered(300 * 200, 0);
  for (const Tile& t : tiles) {
    EXPECT_EQ(t.in_x % kTileAlignment, 0);
    EXPECT_EQ(t.in_width % kTileAlignment, 0);
    EXPECT_EQ(t.in_height % kTileAlignment, 0);
    EXPECT_LE(t.in_width, kMinTileSize);
    // Each written pixel has kTileOverlap pixels of context on either side, or the tile reaches the image's
    // edge (padded to the alignment) there.
    EXPECT_TRUE(t.in_x == 0 || t.out_x - t.in_x >= kTileOverlap);
    EXPECT_TRUE(t.in_x + t.in_width == 304 || t.in_x + t.in_width - (t.out_x + t.out_width) >= kTileOverlap);
    for (int y = t.out_y; y < t.out_y + t.out_height; ++y)
      for (int x = t.out_x; x < t.out_x + t.out_width; ++x) ++covered[size_t(y * 300 + x)];
  }
  for (int c : covered) ASSERT_EQ(c, 1);
}

// Small tiles (3 x 4 of them) give what one pass over the whole image gives, within float noise.
TEST(Denoise, TiledEqualsWhole) {
  const Image color = noisy(smooth(300, 200), 1);
  const Image albedo = filled(300, 200, {0.8f, 0.6f, 0.4f});
  const Image normal = filled(300, 200, {0.f, 0.f, 1.f});
  const DenoiseInputs in{&color, &albedo, &normal};
  const Image whole = denoiser().run(in);
  DenoiseOptions small;
  small.tile_size = 256;
  const Image tiled = denoiser().run(in, small);
  double worst = 0;
  for (size_t i = 0; i < whole.data().size(); ++i)
    worst = std::max(
        worst, std::abs(double(tiled.data()[i]) - whole.data()[i]) / (std::abs(whole.data()[i]) + 1e-3));
  EXPECT_LT(worst, 1e-4);
  std::printf("tiled vs whole: largest relative difference %.2g\n", worst);
}

// A flat image comes back flat and at its level, in both ranges, away from the border (where the network's
// zero padding shows: up to 40% off in a corner pixel, as in OIDN).
TEST(Denoise, ConstantStaysConstant) {
  for (const Range range : {Range::Hdr, Range::Ldr}) {
    const Image color = filled(96, 80, {0.5f, 0.25f, 0.125f});
    DenoiseOptions options;
    options.range = range;
    const Image out = denoiser().run({&color}, options);
    double worst = 0;
    for (int y = 16; y < 80 - 16; ++y)
      for (int x = 16; x < 96 - 16; ++x) {
        const Rgb c = out.at(x, y);
        worst =
            std::max({worst, std::abs(c.x / 0.5 - 1), std::abs(c.y / 0.25 - 1), std::abs(c.z / 0.125 - 1)});
      }
    EXPECT_LT(worst, 0.005) << (range == Range::Hdr ? "hdr" : "ldr");
  }
}

// Noise on a smooth image (exponential for HDR, uniform in [0, 2] on a darker image for LDR, so that no
// value clips): every filter brings the relMSE down by more than 20x (about 250x for HDR, 30x for LDR).
TEST(Denoise, RemovesNoiseFromASmoothImage) {
  const Image albedo = filled(256, 192, {0.7f, 0.7f, 0.7f});
  const Image normal = filled(256, 192, {0.f, 0.f, 1.f});
  for (const Range range : {Range::Hdr, Range::Ldr}) {
    Image clean = smooth(256, 192);
    Image color = noisy(clean, 7);
    if (range == Range::Ldr) {
      std::mt19937 rng(7);
      std::uniform_real_distribution<float> spread(0.f, 2.f);
      for (size_t i = 0; i < clean.data().size(); ++i)
        clean.data()[i] *= 0.5f, color.data()[i] = clean.data()[i] * spread(rng);
    }
    const double before = rel_mse(color, clean);
    EXPECT_GT(before, 0.2);
    const DenoiseInputs inputs[] = {{&color}, {&color, &albedo}, {&color, &albedo, &normal}};
    for (const DenoiseInputs& in : inputs) {
      DenoiseOptions options;
      options.range = range;
      const double after = rel_mse(denoiser().run(in, options), clean);
      EXPECT_LT(after, before / 20) << "range " << int(range) << " albedo " << bool(in.albedo) << " normal "
                                    << bool(in.normal) << ": " << before << " -> " << after;
      std::printf("relMSE %s%s%s: %.4f -> %.5f (%.0fx)\n", range == Range::Hdr ? "hdr" : "ldr",
                  in.albedo ? "+albedo" : "", in.normal ? "+normal" : "", before, after, before / after);
    }
  }
}

// An explicit input scale replaces the autoexposure; scaling the image and the scale together changes
// nothing but the output's scale.
TEST(Denoise, InputScaleMatchesAutoexposure) {
  const Image color = noisy(smooth(64, 48), 3);
  Image brighter = color;
  for (float& v : brighter.data()) v *= 8;
  DenoiseOptions a, b;
  a.input_scale = 2;
  b.input_scale = 0.25;
  const Image out_a = denoiser().run({&color}, a), out_b = denoiser().run({&brighter}, b);
  for (size_t i = 0; i < out_a.data().size(); ++i)
    ASSERT_NEAR(out_b.data()[i], 8 * out_a.data()[i], 1e-4 * (8 * out_a.data()[i]) + 1e-6);
}

TEST(Denoise, BadInputsAreRefused) {
  const Image color = filled(32, 32, {1, 1, 1}), small = filled(16, 32, {1, 1, 1});
  EXPECT_THROW(denoiser().run({}), DenoiseError);
  EXPECT_THROW(denoiser().run({&color, &small}), DenoiseError);
  EXPECT_THROW(denoiser().run({&color, &color, &small}), DenoiseError);
  EXPECT_THROW(denoiser().run({&color, nullptr, &color}), DenoiseError);
  DenoiseOptions options;
  options.tile_size = 64;
  EXPECT_THROW(denoiser().run({&color}, options), DenoiseError);
  EXPECT_THROW(Denoiser("/nonexistent").run({&color}), DenoiseError);
}

TEST(Denoise, ProgressCancels) {
  const Image color = filled(300, 200, {1, 1, 1});
  DenoiseOptions options;
  options.tile_size = kMinTileSize;
  std::vector<double> seen;
  options.progress = [&](double f) {
    seen.push_back(f);
    return seen.size() < 3;
  };
  EXPECT_THROW(denoiser().run({&color}, options), DenoiseCancelled);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0], 0);
  EXPECT_GT(seen[2], seen[1]);
}

}  // namespace
}  // namespace lp::denoise

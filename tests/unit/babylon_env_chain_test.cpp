// A cube chain as Babylon's .env: Babylon's cube in direction d holds ours in direction (-d.x, d.y, d.z)
// (the frame of babylon_env_chain.hpp; its images bottom row first), every level of the full chain is in the
// file as RGBD PNG, the levels past the chain's are box averages, and the polynomial is there.
#include "engine/image/babylon_env_chain.hpp"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/babylon_env.hpp"
#include "engine/image/rgbd.hpp"
#include "engine/projection/cube_face.hpp"

namespace lp {
namespace {

// Texel (i, j) of face f at level l: (f + 1, i + 1 + 10 l, j + 1).
PrefilteredChain numbered_chain(int base_size, int levels) {
  PrefilteredChain chain;
  chain.params.projection = Projection::Cube;
  chain.params.base_size = base_size;
  chain.params.levels = levels;
  for (int l = 0; l < levels; ++l) {
    const int n = base_size >> l;
    Image strip(6 * n, n);
    for (int f = 0; f < 6; ++f)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          strip.set(f * n + i, j, {float(f + 1), float(i + 1 + 10 * l), float(j + 1)});
    chain.levels.push_back(strip);
  }
  return chain;
}

Rgb texel_at(const Image& strip_or_face, int face, Vec3d d, bool strip) {
  const CubeFacePoint p = cube_face_point(d);
  EXPECT_EQ(p.face, face);
  const int n = strip_or_face.height();
  const int i = std::min(n - 1, int((p.ab.x + 1) / 2 * n)), j = std::min(n - 1, int((p.ab.y + 1) / 2 * n));
  // A Babylon image holds row j of the face at row n - 1 - j.
  return strip_or_face.at((strip ? p.face * n : 0) + i, strip ? j : n - 1 - j);
}

TEST(BabylonEnvChain, BabylonsCubeInDirectionDHoldsOursMirroredInX) {
  const PrefilteredChain chain = numbered_chain(8, 1);
  for (const Vec3d d : {Vec3d{1, 0.3, -0.6}, Vec3d{-1, 0.7, 0.2}, Vec3d{0.4, 1, -0.3}, Vec3d{-0.45, -1, 0.6},
                        Vec3d{0.7, -0.2, 1}, Vec3d{-0.3, 0.55, -1}}) {
    const int face = cube_face_point(d).face;
    const Image ours = chain.levels[0];
    EXPECT_EQ(texel_at(babylon_face(ours, face), face, d, false),
              texel_at(ours, cube_face_point({-d.x, d.y, d.z}).face, {-d.x, d.y, d.z}, true))
        << d.x << " " << d.y << " " << d.z;
  }
}

Image decode_png_rgbd(const std::vector<uint8_t>& png) {
  int w = 0, h = 0, channels = 0;
  uint8_t* pixels = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &channels, 4);
  EXPECT_NE(pixels, nullptr);
  Image image = decode_rgbd_pixels(std::span<const uint8_t>(pixels, size_t(w) * size_t(h) * 4), w, h);
  stbi_image_free(pixels);
  return image;
}

TEST(BabylonEnvChain, WritesEveryLevelDownToOneTexel) {
  const PrefilteredChain chain = numbered_chain(8, 2);
  ShCoefficients sh;
  sh.bands = 3;
  sh.rgb.assign(9, {0, 0, 0});
  sh.rgb[0] = {1, 1, 1};
  const BabylonEnv env = read_babylon_env(babylon_env_file(chain, sh));
  EXPECT_EQ(env.width, 8);
  ASSERT_EQ(env.specular.size(), 4u * 6);  // 8, 4, 2 and 1 texels
  ASSERT_TRUE(env.irradiance);
  EXPECT_GT(env.irradiance->xx[0], 0);
  for (int level = 0; level < 4; ++level)
    for (int f = 0; f < 6; ++f) {
      const Image face = decode_png_rgbd(env.specular[size_t(level * 6 + f)]);
      ASSERT_EQ(face.width(), 8 >> level);
      // Our face for Babylon's face f, its texels' mean: x = ours + 1; y the mean column of level
      // min(level, 1) + 1, mirrored or not; z the mean row + 1, upside down or not.
      const float ours = float(f == 0 ? 1 : f == 1 ? 0 : f) + 1;
      const int n = 8 >> std::min(level, 1);
      const float mean_y = float(n + 1) / 2 + 10 * float(std::min(level, 1)), mean_z = float(n + 1) / 2;
      Rgb sum{};
      for (int y = 0; y < face.height(); ++y)
        for (int x = 0; x < face.width(); ++x) sum += face.at(x, y);
      const Rgb mean = sum / float(face.width() * face.height());
      // RGBD keeps each texel to 0.6% of its brightest channel (at most 18 here).
      EXPECT_NEAR(mean.x, ours, 0.11) << level << " " << f;
      EXPECT_NEAR(mean.y, mean_y, 0.11) << level << " " << f;
      EXPECT_NEAR(mean.z, mean_z, 0.11) << level << " " << f;
    }
  // Level 0's first texel of Babylon's +X is our -X's last column, last row.
  const Rgb first = decode_png_rgbd(env.specular[0]).at(0, 0);
  EXPECT_NEAR(first.y, 8, 0.05);
  EXPECT_NEAR(first.z, 8, 0.05);
}

TEST(BabylonEnvChain, RefusesOtherProjectionsAndSizes) {
  PrefilteredChain chain = numbered_chain(8, 1);
  ShCoefficients sh;
  sh.bands = 3;
  sh.rgb.assign(9, {0, 0, 0});
  chain.params.projection = Projection::LatLong;
  EXPECT_THROW(babylon_env_file(chain, sh), Error);
  chain = numbered_chain(12, 1);
  EXPECT_THROW(babylon_env_file(chain, sh), Error);
}

}  // namespace
}  // namespace lp

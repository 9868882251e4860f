// The prefiltered specular chain against analytic answers: a constant map stays constant at every level
// of every projection, level 0 keeps the map's power, and every level (lat-long and cube faces) matches
// a brute-force GGX convolution over all the pixels of real maps. Also the map the lobes read,
// determinism, progress and stopping.
#include "engine/prefilter/prefilter_chain.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "engine/bsdf/microfacet.hpp"
#include "engine/core/error.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/prefilter/prefilter_source.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/projection_texels.hpp"
#include "support/constant_map.hpp"
#include "support/real_maps.hpp"

namespace lp {
namespace {

PrefilterParams params(int levels, int base_size, int samples, Projection projection = Projection::LatLong) {
  PrefilterParams p;
  p.levels = levels, p.base_size = base_size, p.samples = samples, p.projection = projection;
  return p;
}

// The split-sum lobe integrated over the map, each pixel cut into 2 x 2 parts with their own exact solid
// angles and the pixel's radiance: sum L n.l D(h) dw / sum n.l D(h) dw over the hemisphere around n.
Rgb brute_force(const EnvMap& map, Vec3 n, double roughness) {
  const render::Ggx ggx(float(roughness * roughness));
  const int k = 2, w = map.width() * k, h = map.height() * k;
  double sum[3] = {0, 0, 0}, total = 0;
  for (int y = 0; y < h; ++y) {
    const double omega = latlong::pixel_solid_angle(y, w, h);
    for (int x = 0; x < w; ++x) {
      const Vec3 l = latlong::direction({(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)});
      const float nl = dot(n, l);
      if (nl <= 0) continue;
      const double weight = double(nl) * ggx.d({0, 0, dot(n, normalize(n + l))}) * omega;
      const Rgb c = map.image().at(x / k, y / k);
      sum[0] += weight * c.x, sum[1] += weight * c.y, sum[2] += weight * c.z;
      total += weight;
    }
  }
  return Rgb{float(sum[0]), float(sum[1]), float(sum[2])} / float(total);
}

struct Errors {
  double worst = 0, mean = 0;
};

// Relative errors of the sum of the channels at 8 texels of a level spread over the sphere.
Errors errors_against_brute_force(const EnvMap& map, const PrefilteredChain& chain, int level) {
  const latlong::Uv points[] = {{0.05f, 0.1f}, {0.3f, 0.3f},   {0.55f, 0.45f}, {0.8f, 0.55f},
                                {0.15f, 0.7f}, {0.45f, 0.85f}, {0.7f, 0.95f},  {0.95f, 0.5f}};
  const Image& image = chain.levels[size_t(level)];
  Errors e;
  for (const latlong::Uv uv : points) {
    const int x = latlong::pixel_x(uv.u, image.width()), y = latlong::pixel_y(uv.v, image.height());
    const Vec3 n = latlong::direction(
        {(float(x) + 0.5f) / float(image.width()), (float(y) + 0.5f) / float(image.height())});
    const Rgb want = brute_force(map, n, chain.params.roughness(level)), got = image.at(x, y);
    const double error = std::abs(double(got.x + got.y + got.z) / double(want.x + want.y + want.z) - 1);
    e.worst = std::max(e.worst, error);
    e.mean += error / std::size(points);
  }
  return e;
}

TEST(PrefilterChain, AConstantMapIsOneAtEveryLevel) {
  const EnvMap white = test::constant_map(256, 128, {1, 1, 1});
  const PrefilterParams defaults;
  const auto chain = prefilter_chain(white, defaults);
  ASSERT_TRUE(chain);
  ASSERT_EQ(int(chain->levels.size()), defaults.levels);
  for (size_t i = 0; i < chain->levels.size(); ++i) {
    const Image& level = chain->levels[i];
    EXPECT_EQ(level.width(), defaults.base_size >> i);
    EXPECT_EQ(level.height(), defaults.base_size / 2 >> i);
    const auto [lo, hi] = std::minmax_element(level.data().begin(), level.data().end());
    EXPECT_NEAR(*lo, 1.0f, 1e-3f) << "level " << i;
    EXPECT_NEAR(*hi, 1.0f, 1e-3f) << "level " << i;
  }
}

// Level 0 resamples a constant exactly; a level above sums weights that add up to one, read trilinearly
// from levels of ones: float rounding alone, well under 1e-4.
TEST(PrefilterChain, AConstantMapIsOneAtEveryLevelOfEveryProjection) {
  const EnvMap white = test::constant_map(256, 128, {1, 1, 1});
  for (const auto& [projection, name] : enum_entries(Projection{})) {
    const PrefilterParams p = params(4, 32, 64, projection);
    const auto chain = prefilter_chain(white, p);
    ASSERT_TRUE(chain);
    ASSERT_EQ(int(chain->levels.size()), p.levels);
    for (int i = 0; i < p.levels; ++i) {
      const Image& level = chain->levels[size_t(i)];
      const ImageShape shape = projection_shape(projection, 32 >> i);
      ASSERT_EQ(level.width(), shape.width) << name << " level " << i;
      ASSERT_EQ(level.height(), shape.height) << name << " level " << i;
      for (int y = 0; y < level.height(); ++y)
        for (int x = 0; x < level.width(); ++x) {
          // The six empty cells of a cross are black.
          const bool face = projection != Projection::Cross || cube_layout_texel(projection, 32 >> i, x, y);
          const Rgb v = level.at(x, y);
          ASSERT_NEAR(v.x, face ? 1.0f : 0.0f, 1e-4f)
              << name << " level " << i << " texel " << x << ", " << y;
          ASSERT_NEAR(v.z, face ? 1.0f : 0.0f, 1e-4f)
              << name << " level " << i << " texel " << x << ", " << y;
        }
    }
  }
}

TEST(PrefilterChain, LevelZeroKeepsThePowerOfTheMap) {
  const auto map = test::real_map("sunrise.exr");  // 256 x 128 with a sun of a few pixels
  for (const int base : {64, 100, 256, 512}) {
    const auto chain = prefilter_chain(*map, params(1, base, 16));
    const Rgb power = EnvMap::power_of(chain->levels[0]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c] / map->power()[c], 1.0, 1e-5) << "base " << base;
  }
}

// Measured over 32 texels a level of the maps of tests/data without a sun (forest, courtyard, city) with
// 1024 samples: the mean relative error of a level is 0.7% to 4.1%, single texels up to 13% (dark
// texels beside bright ones); 4096 samples halve it. The brute force itself is converged: 4 x 4 parts
// a pixel, or the map interpolated bilinearly, change these figures by less than 0.2%.
TEST(PrefilterChain, MatchesABruteForceConvolutionOfRealMaps) {
  for (const char* file : {"forest.exr", "courtyard.exr"}) {
    const auto map = test::real_map(file);
    const auto chain = prefilter_chain(*map, params(6, 64, 1024));
    for (int level = 1; level < 6; ++level) {
      const Errors e = errors_against_brute_force(*map, *chain, level);
      EXPECT_LT(e.mean, 0.05) << file << " level " << level;
      EXPECT_LT(e.worst, 0.15) << file << " level " << level;
    }
  }
}

// A sun of a few pixels is what filtered importance sampling does worst: each sample sees the sun
// through a mip texel about as large as the gap between samples, so a texel's error does not shrink
// with more samples as fast (measured with 4096 samples: level means 0.4% to 3.7%, single texels 22%).
TEST(PrefilterChain, MatchesABruteForceConvolutionOfAMapWithASun) {
  const auto map = test::real_map("sunrise.exr");
  const auto chain = prefilter_chain(*map, params(6, 64, 4096));
  for (int level = 1; level < 6; ++level) {
    const Errors e = errors_against_brute_force(*map, *chain, level);
    EXPECT_LT(e.mean, 0.06) << "level " << level;
    EXPECT_LT(e.worst, 0.25) << "level " << level;
  }
}

// Cube faces are convolved at their own texels by the same lobes (measured on forest with 1024 samples,
// faces of 32 texels, the 10 texels below: level means 0.8% to 1.7%, single texels up to 4.3%).
TEST(PrefilterChain, CubeFacesMatchABruteForceConvolution) {
  const auto map = test::real_map("forest.exr");
  const auto chain = prefilter_chain(*map, params(5, 32, 1024, Projection::Cube));
  // Texels on every face, at centres, edges and corners.
  const FaceTexel texels[] = {{0, 1, 1}, {0, 8, 8}, {1, 7, 0}, {2, 3, 5}, {2, 0, 0},
                              {3, 6, 6}, {3, 1, 7}, {4, 0, 4}, {5, 7, 7}, {5, 4, 2}};
  for (int level = 1; level < 5; ++level) {
    const Image& image = chain->levels[size_t(level)];
    const int size = 32 >> level;
    ASSERT_EQ(image.width(), 6 * size);
    ASSERT_EQ(image.height(), size);
    Errors e;
    for (FaceTexel t : texels) {
      t.i = std::min(t.i, size - 1), t.j = std::min(t.j, size - 1);
      const Pixel p = cube_layout_pixel(Projection::Cube, size, t);
      const Vec3 n =
          to_float(texel_centre_direction(Projection::Cube, {image.width(), image.height()}, p.x, p.y));
      const Rgb want = brute_force(*map, n, chain->params.roughness(level)), got = image.at(p.x, p.y);
      const double error = std::abs(double(got.x + got.y + got.z) / double(want.x + want.y + want.z) - 1);
      e.worst = std::max(e.worst, error);
      e.mean += error / std::size(texels);
    }
    EXPECT_LT(e.mean, 0.03) << "level " << level;
    EXPECT_LT(e.worst, 0.08) << "level " << level;
  }
}

// A texel's value is a function of its direction alone: the same direction in two projections has the
// same value, and a cross is the cube's strip laid out.
TEST(PrefilterChain, ProjectionsAgreeWhereTheirTexelsLookTheSameWay) {
  const auto map = test::real_map("courtyard.exr");
  const auto cube = prefilter_chain(*map, params(3, 16, 64, Projection::Cube));
  const auto cross = prefilter_chain(*map, params(3, 16, 64, Projection::Cross));
  for (size_t i = 0; i < cube->levels.size(); ++i) {
    const Image laid_out = cube_relayout(cube->levels[i], Projection::Cube, Projection::Cross);
    EXPECT_TRUE(std::equal(laid_out.data().begin(), laid_out.data().end(), cross->levels[i].data().begin()))
        << "level " << i;
  }
  // The centre of face pz (looking at -y) is the texel of a 64 x 32 lat-long level at phi = 3 pi / 2 on
  // the equator: between texels (47, 15) and (48, 16), so their mean.
  const auto latlong = prefilter_chain(*map, params(3, 64, 64));
  for (int level = 1; level < 3; ++level) {
    const Image& faces = cube->levels[size_t(level)];
    const int size = faces.height();
    const Pixel c = cube_layout_pixel(Projection::Cube, size, {4, size / 2, size / 2});
    const Rgb around =
        (faces.at(c.x, c.y) + faces.at(c.x - 1, c.y - 1) + faces.at(c.x - 1, c.y) + faces.at(c.x, c.y - 1)) /
        4.0f;
    const Image& ll = latlong->levels[size_t(level)];
    const int x = ll.width() * 3 / 4, y = ll.height() / 2;
    const Rgb want = (ll.at(x, y) + ll.at(x - 1, y - 1) + ll.at(x - 1, y) + ll.at(x, y - 1)) / 4.0f;
    EXPECT_NEAR(around.y / want.y, 1.0, 0.05) << "level " << level;
  }
}

TEST(PrefilterChain, TheLobesReadTheMapReducedToWhatTheirSamplesResolve) {
  const PrefilterParams defaults;  // level 1 at roughness 0.2, 1024 samples
  EXPECT_EQ(PrefilterSource::width_for(8192, defaults), 1024);
  EXPECT_EQ(PrefilterSource::width_for(256, defaults), 256);  // never finer than the map
  EXPECT_EQ(PrefilterSource::width_for(8192, params(6, 256, 4096)), 2048);
  EXPECT_EQ(PrefilterSource::width_for(8192, params(11, 2048, 16384)), 2048);  // at most 2048
  EXPECT_EQ(PrefilterSource::width_for(8192, params(3, 256, 64)), 32);
  const auto chain = prefilter_chain(*test::real_map("forest.exr"), params(6, 64, 64));
  EXPECT_EQ(chain->source_width, 256);
}

TEST(PrefilterChain, IsTheSameWhateverTheThreadCount) {
  const auto map = test::real_map("studio.exr");
  const PrefilterParams p = params(5, 64, 256);
  const auto parallel = prefilter_chain(*map, p);
  std::optional<PrefilteredChain> serial;
  tbb::task_arena(1).execute([&] { serial = prefilter_chain(*map, p); });
  for (size_t i = 0; i < parallel->levels.size(); ++i) {
    const std::span<const float> a = parallel->levels[i].data(), b = serial->levels[i].data();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size_bytes()), 0) << "level " << i;
  }
}

TEST(PrefilterChain, ReportsEveryWorkUnitAndStopsWhenAsked) {
  const auto map = test::real_map("forest.exr");
  const PrefilterParams p = params(4, 32, 64);
  std::atomic<int64_t> units{0};
  const auto done = prefilter_chain(*map, p, {nullptr, [&](int64_t u) { units += u; }});
  ASSERT_TRUE(done);
  EXPECT_EQ(units.load(), prefilter_work_units(p));
  EXPECT_EQ(prefilter_work_units(p), 32 * 16 + (16 * 8 + 8 * 4 + 4 * 2) * 64);

  std::atomic<int> rows{0};
  const auto stopped = prefilter_chain(*map, p, {[&] { return rows.load() > 0; }, [&](int64_t) { ++rows; }});
  EXPECT_FALSE(stopped);
}

TEST(PrefilterChain, RefusesParametersOutOfRange) {
  const auto map = test::real_map("forest.exr");
  try {
    prefilter_chain(*map, params(9, 256, 64));
    ADD_FAILURE() << "accepted 9 levels of a 256-wide base";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "levels");
  }
  EXPECT_THROW(prefilter_chain(*map, params(6, 256, 8)), Error);
  EXPECT_THROW(prefilter_chain(*map, params(2, 4096, 64)), Error);
  try {
    prefilter_chain(*map, params(4, 100, 64, Projection::Cross));  // level 3 would be 12.5 texels a face
    ADD_FAILURE() << "accepted a cross of 100 texels a face and 4 levels";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "base_size");
  }
  EXPECT_TRUE(prefilter_chain(*map, params(3, 100, 16, Projection::Cross)));  // 100, 50, 25
  EXPECT_TRUE(prefilter_chain(*map, params(4, 100, 16, Projection::Cube)));
}

}  // namespace
}  // namespace lp

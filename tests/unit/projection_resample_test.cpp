// Resampling between projections: a constant map stays constant in every projection, the power (sum of
// radiance times texel solid angle) is kept, each texel holds the radiance of its own directions, and
// the result does not depend on the thread count. Round trips lat-long -> cube -> lat-long on the maps of
// tests/data and on synthetic ones keep the power to 1e-3 (the figures reached are far below it).
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <functional>

#include "engine/core/constants.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/projection/projection_texels.hpp"
#include "engine/projection/reproject.hpp"
#include "support/real_maps.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

constexpr Projection kOthers[] = {Projection::Cube, Projection::Cross, Projection::Octahedral,
                                  Projection::EqualArea};

Image map_of(Projection p, int size, const std::function<Rgb(Vec3d)>& radiance) {
  const ImageShape shape = projection_shape(p, size);
  Image image(shape.width, shape.height);
  for (int y = 0; y < shape.height; ++y)
    for (int x = 0; x < shape.width; ++x) {
      const Vec3d d = texel_centre_direction(p, shape, x, y);
      if (d != Vec3d{}) image.set(x, y, radiance(d));
    }
  return image;
}

double relative_error(Rgb a, Rgb b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(a[c]) - b[c]) / std::abs(double(b[c])));
  return worst;
}

Rgb power(const Image& image, Projection p) {
  return projected_power(image, p);
}

// A bright disc `radius_deg` in radius (a sun: most of the power in a few pixels) over a dim sky.
std::function<Rgb(Vec3d)> sunny(double radius_deg) {
  return [radius_deg](Vec3d d) {
    const Vec3d sun = normalize(Vec3d{0.3, -0.5, 0.6});
    if (angle_between(d, sun) < radius_deg * kPi / 180) return Rgb{20000, 18000, 15000};
    return Rgb{0.2f + 0.1f * float(d.z), 0.3f, 0.5f};
  };
}

TEST(ProjectionResample, AConstantMapStaysExactlyConstant) {
  const Rgb c{1, 2, 0.5f};
  const auto constant = [c](Vec3d) { return c; };
  const Image latlong = map_of(Projection::LatLong, 64, constant);
  for (const Projection p : kOthers)
    for (const int size : {5, 16, 33}) {
      const Image to = reproject(latlong, Projection::LatLong, p, size);
      const ImageShape shape = projection_shape(p, size);
      for (int y = 0; y < shape.height; ++y)
        for (int x = 0; x < shape.width; ++x) {
          const bool empty = texel_centre_direction(p, shape, x, y) == Vec3d{};
          for (int ch = 0; ch < 3; ++ch)
            ASSERT_NEAR(to.at(x, y)[ch], empty ? 0 : c[ch], 1e-6 * c[ch])
                << enum_name(p) << " " << x << "," << y;
        }
      const Image back = reproject(to, p, Projection::LatLong, 48);
      for (int y = 0; y < back.height(); ++y)
        for (int x = 0; x < back.width(); ++x)
          for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(back.at(x, y)[ch], c[ch], 1e-6 * c[ch]) << enum_name(p);
      for (const Projection q : kOthers) {
        const Image across = reproject(to, p, q, 7);
        const Vec3d d = texel_centre_direction(q, projection_shape(q, 7), 3, 3);
        if (d != Vec3d{}) {
          ASSERT_NEAR(across.at(3, 3)[1], c[1], 1e-6) << enum_name(p) << " to " << enum_name(q);
        }
      }
    }
}

// Each channel a linear function of one coordinate: a texel's mean over its footprint is the function at
// the footprint's centroid, within a fraction of a texel of its centre. Checks every convention at once.
TEST(ProjectionResample, EachTexelHoldsTheRadianceOfItsDirections) {
  const auto gradient = [](Vec3d d) { return Rgb{float(2 + d.x), float(2 + d.y), float(2 + d.z)}; };
  const Image latlong = map_of(Projection::LatLong, 512, gradient);
  for (const Projection p : kOthers) {
    const int size = 32;
    const Image to = reproject(latlong, Projection::LatLong, p, size);
    const ImageShape shape = projection_shape(p, size);
    for (int y = 0; y < shape.height; ++y)
      for (int x = 0; x < shape.width; ++x) {
        const Vec3d d = texel_centre_direction(p, shape, x, y);
        if (d == Vec3d{}) continue;
        const Rgb expected = gradient(d);
        for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(to.at(x, y)[ch], expected[ch], 0.05) << enum_name(p);
      }
    const Image back = reproject(to, p, Projection::LatLong, 128);
    const ImageShape ll = projection_shape(Projection::LatLong, 128);
    for (int y = 0; y < ll.height; ++y)
      for (int x = 0; x < ll.width; ++x) {
        const Rgb expected = gradient(texel_centre_direction(Projection::LatLong, ll, x, y));
        for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(back.at(x, y)[ch], expected[ch], 0.08) << enum_name(p);
      }
  }
}

// Power kept from lat-long into each projection and back, on a smooth map and on a sunny one (a sun 3
// degrees across, 4 pixels of the 512 x 256 map).
TEST(ProjectionResample, PowerIsKeptBothWays) {
  const auto smooth = [](Vec3d d) {
    return Rgb{float(1 + d.x * d.y + 0.5 * d.z), float(2 + d.x * d.x * d.x), float(0.3 + d.y * d.y)};
  };
  for (const auto& [name, radiance] :
       {std::pair<const char*, std::function<Rgb(Vec3d)>>{"smooth", smooth}, {"sunny", sunny(1.5)}}) {
    const Image latlong = map_of(Projection::LatLong, 512, radiance);
    const Rgb original = power(latlong, Projection::LatLong);
    for (const Projection p : kOthers) {
      const int size = equivalent_size(p, 512);
      const Image to = reproject(latlong, Projection::LatLong, p, size);
      EXPECT_LT(relative_error(power(to, p), original), 1e-4) << name << " to " << enum_name(p);
      const Image native = map_of(p, size, radiance);
      const Image back = reproject(native, p, Projection::LatLong, 512);
      EXPECT_LT(relative_error(power(back, Projection::LatLong), power(native, p)), 1e-4)
          << name << " from " << enum_name(p);
    }
  }
}

// The test: lat-long -> cube -> lat-long keeps the power to 1e-3, on every map of tests/data
// (256 x 128, cube faces of 64) and on a sunny synthetic map (1024 x 512, faces of 256).
TEST(ProjectionResample, LatLongToCubeAndBackKeepsThePower) {
  std::vector<std::pair<std::string, Image>> maps;
  for (const std::string& file : test::real_envmap_files())
    maps.emplace_back(file, test::real_map(file)->image());
  maps.emplace_back("sunny", map_of(Projection::LatLong, 1024, sunny(0.5)));  // a sun 3 pixels across
  for (const auto& [name, latlong] : maps) {
    const Rgb original = EnvMap::power_of(latlong);
    const int face = equivalent_size(Projection::Cube, latlong.width());
    const Image cube = reproject(latlong, Projection::LatLong, Projection::Cube, face);
    const Image back = reproject(cube, Projection::Cube, Projection::LatLong, latlong.width());
    ASSERT_EQ(back.width(), latlong.width());
    ASSERT_EQ(back.height(), latlong.height());
    const double to_cube = relative_error(power(cube, Projection::Cube), original);
    const double round_trip = relative_error(EnvMap::power_of(back), original);
    EXPECT_LT(round_trip, 1e-3) << name;
    EXPECT_LT(to_cube, 5e-5) << name;  // what the resampling reaches: 1e-6 to 1e-5
    EXPECT_LT(round_trip, 5e-5) << name;
    std::printf("%s: power error to the cube %.2e, round trip %.2e\n", name.c_str(), to_cube, round_trip);
  }
}

TEST(ProjectionResample, TheResultDoesNotDependOnTheThreadCount) {
  const Image latlong = test::real_map("sunrise.exr")->image();
  const Image many = reproject(latlong, Projection::LatLong, Projection::EqualArea, 96);
  tbb::task_arena one(1);
  Image single;
  one.execute([&] { single = reproject(latlong, Projection::LatLong, Projection::EqualArea, 96); });
  ASSERT_EQ(many.data().size(), single.data().size());
  for (size_t i = 0; i < many.data().size(); ++i) ASSERT_EQ(many.data()[i], single.data()[i]) << i;
}

TEST(ProjectionResample, AShapeThatDoesNotFitIsRefused) {
  const Image not_square(10, 12);
  EXPECT_THROW(reproject(not_square, Projection::EqualArea, Projection::LatLong, 16), Error);
  const Image not_cross(40, 31);
  EXPECT_THROW(reproject(not_cross, Projection::Cross, Projection::LatLong, 16), Error);
}

}  // namespace
}  // namespace lp

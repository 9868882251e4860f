// Sun extraction against maps with a sun of known direction and power added (support/sunny_map.hpp): to
// a smooth analytic sky and to the real maps of tests/data. The residual and the sun add up to the map
// exactly; maps without a compact emitter have no sun.
#include "engine/sun/sun_extraction.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "engine/core/constants.hpp"
#include "support/real_maps.hpp"
#include "support/sunny_map.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using test::AddedSun;

// Direction within one pixel (its height), power within `power_tolerance` per channel, and the sums exact.
void expect_found(const SunExtraction& e, const AddedSun& added, int height, const std::string& what,
                  double power_tolerance = 0.01) {
  ASSERT_TRUE(e.sun) << what << ": " << e.reason;
  const Sun& sun = *e.sun;
  const double pixel = kPi / height;
  EXPECT_LT(angle_between(sun.axis, added.axis), pixel) << what;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sun.power[c] / added.power[c], 1.0, power_tolerance) << what << " channel " << c;
    EXPECT_EQ(e.residual_power[c] + sun.power[c], e.map_power[c]) << what << " channel " << c;
  }
  std::printf("%s: off by %.3f pixels, power %.5f of the added, radius %.3f deg (added %.3f), share %.3f\n",
              what.c_str(), angle_between(sun.axis, added.axis) / pixel, sun.power[0] / added.power[0],
              sun.angular_radius * 180 / kPi, added.radius * 180 / kPi, sun.share);
}

TEST(SunExtraction, FindsASunAddedToASmoothSky) {
  struct Case {
    double theta_deg, phi_deg, radius_deg;
  };
  // Mid-sky, on the horizon at the seam, beside the seam, by either pole, below the horizon, small.
  const Case cases[] = {{60, 120, 1.5},  {85, 0.2, 1.5}, {30, 359.5, 0.8}, {1, 40, 2},
                        {120, 200, 1.5}, {179.5, 10, 1}, {45, 90, 0.6}};
  for (const Case& c : cases) {
    Image image = test::latlong_image(512, test::smooth_sky);
    // About 70% of the map's power whatever the radius.
    const float radiance = float(9000 / (c.radius_deg * c.radius_deg));
    const AddedSun added =
        test::add_sun(image, c.theta_deg, c.phi_deg, c.radius_deg, Rgb{1.0f, 0.9f, 0.75f} * radiance);
    const EnvMap map(std::move(image));
    expect_found(extract_sun(map, SunParams{}), added, map.height(),
                 fmt::format("theta {} phi {} radius {}", c.theta_deg, c.phi_deg, c.radius_deg));
  }
}

// A low sun a person plainly sees that carries only 2% of the map's power: found by its radiance and
// compactness, in the right direction and of the right size.
TEST(SunExtraction, FindsALowSunOfTwoPercentOfThePower) {
  struct Case {
    double theta_deg, phi_deg, radius_deg;
  };
  const Case cases[] = {{86, 215, 1.0}, {80, 30, 0.5}, {88, 359.8, 1.5}};
  for (const Case& c : cases) {
    Image image = test::latlong_image(1024, test::smooth_sky);
    const Rgb sky = EnvMap::power_of(image);
    const Rgb tint{1.0f, 0.7f, 0.4f};  // luminance (R + G + B) / 3 = 0.7
    const double omega = cone_solid_angle(c.radius_deg * kPi / 180);
    // 2% of the luminous power of sky and sun together: sun = 0.02 / 0.98 sky.
    const double sky_luminance = (sky.x + sky.y + sky.z) / 3;
    const AddedSun added = test::add_sun(image, c.theta_deg, c.phi_deg, c.radius_deg,
                                         tint * float(0.02 / 0.98 * sky_luminance / omega / 0.7));
    const EnvMap map(std::move(image));
    const SunExtraction e = extract_sun(map, SunParams{});
    const std::string what = fmt::format("theta {} phi {} radius {}", c.theta_deg, c.phi_deg, c.radius_deg);
    // Power within 2%: at the horizon the ring's mean misjudges the steep sky under the disc by about
    // 0.03% of the map's power, which is 1.5% of a sun this faint.
    expect_found(e, added, map.height(), what, 0.02);
    if (!e.sun) continue;
    EXPECT_NEAR(e.sun->share, 0.02, 0.002) << what;
    // The core's solid angle is the disc's pixels': its radius within half a pixel of the disc's.
    EXPECT_NEAR(e.sun->angular_radius * 180 / kPi, c.radius_deg, 0.5 * 180.0 / map.height()) << what;
  }
}

// Bright regions that are no sun: an overcast sky brightest at the zenith, an overcast sky with the glow
// of a sun behind the clouds (bright, but spread over tens of degrees), and a room lit by a big window.
TEST(SunExtraction, NoSunInAnOvercastSkyOrABigWindow) {
  const Direction glow_axis = pixel_centre_direction(300, 180, 1024, 512);
  const auto overcast = [](Vec3 d) {
    return d.z < 0 ? Rgb{0.2f, 0.2f, 0.2f} : Rgb{1, 1, 1} * (1 + 2 * d.z) / 3;
  };
  const auto glow = [&](Vec3 d) {
    const double a = angle_between({d.x, d.y, d.z}, glow_axis) * 180 / kPi;
    return overcast(d) + Rgb{1, 1, 1} * float(20 * std::exp(-a * a / (2 * 8 * 8)));
  };
  // A window 30 degrees wide and tall at the horizon, 100 times as bright as the walls.
  const auto room = [](Vec3 d) {
    const double theta = std::acos(d.z) * 180 / kPi, phi = std::atan2(d.y, d.x) * 180 / kPi;
    const bool window = theta > 60 && theta < 90 && phi > 80 && phi < 110;
    return window ? Rgb{20, 21, 22} : Rgb{0.2f, 0.19f, 0.18f};
  };
  const std::pair<const char*, std::function<Rgb(Vec3)>> maps[] = {
      {"overcast", overcast}, {"glow", glow}, {"window", room}};
  for (const auto& [name, f] : maps) {
    const EnvMap map(test::latlong_image(1024, f));
    const SunExtraction e = extract_sun(map, SunParams{});
    EXPECT_FALSE(e.sun) << name << ": found a sun of share " << (e.sun ? e.sun->share : 0);
    std::printf("%s: %s\n", name, e.reason.c_str());
  }
}

// A faint disc (its core the disc alone at threshold 0.5) under min_contrast or under min_share is no
// sun; lowering min_contrast finds it, raising min_share loses it again.
TEST(SunExtraction, TheThresholdsDecide) {
  Image image = test::latlong_image(512, test::smooth_sky);
  test::add_sun(image, 70, 100, 4, Rgb{5, 5, 5});  // about 7 times the sky around it, 1% of the power
  const EnvMap map(std::move(image));
  SunParams base;
  base.threshold = 0.5;
  const SunExtraction under = extract_sun(map, base);
  EXPECT_FALSE(under.sun);
  EXPECT_NE(under.reason.find("min_contrast"), std::string::npos) << under.reason;
  SunParams lenient = base;
  lenient.min_contrast = 3;
  const SunExtraction e = extract_sun(map, lenient);
  ASSERT_TRUE(e.sun) << e.reason;
  EXPECT_GT(e.sun->contrast, 3);
  EXPECT_LT(e.sun->contrast, base.min_contrast);
  SunParams strict = lenient;
  strict.min_share = 2 * e.sun->share;
  EXPECT_FALSE(extract_sun(map, strict).sun);
}

TEST(SunExtraction, NoSunInAConstantSmoothOrBlackMap) {
  const EnvMap constant(test::latlong_image(128, [](Vec3) { return Rgb{1, 1, 1}; }));
  const EnvMap smooth(test::latlong_image(256, test::smooth_sky));
  const EnvMap black(test::latlong_image(64, [](Vec3) { return Rgb{}; }));
  for (const EnvMap* map : {&constant, &smooth, &black}) {
    const SunExtraction e = extract_sun(*map, SunParams{});
    EXPECT_FALSE(e.sun) << e.reason;
    EXPECT_FALSE(e.reason.empty());
    EXPECT_EQ(e.residual, nullptr);
    EXPECT_EQ(e.residual_power, e.map_power);
    std::printf("no sun: %s\n", e.reason.c_str());
  }
}

TEST(SunExtraction, FindsASunAddedToEveryRealMapWithoutOne) {
  // A sun of 3 degrees (about 2 pixels of 1.4 degrees) with twice the map's power. Not to city, forest
  // or sunrise: a sky has one sun, and of two the detection takes neither (kSunPeakOverElsewhere).
  for (const auto& file : test::real_envmap_files()) {
    if (extract_sun(*test::real_map(file), SunParams{}).sun) continue;
    Image image = test::real_map(file)->image();
    const double map_power = EnvMap::power_of(image).x;
    const float radiance = float(2 * map_power / cone_solid_angle(3 * kPi / 180));
    const AddedSun added = test::add_sun(image, 70, 60, 3, Rgb{radiance, radiance, radiance});
    const EnvMap map(std::move(image));
    expect_found(extract_sun(map, SunParams{}), added, map.height(), file);
  }
}

TEST(SunExtraction, TheSunsOfTheRealMaps) {
  // city, forest and sunrise have a sun: a small bright disc at the map's size. courtyard's brightest
  // spot is spread along sunlit walls and the studio's lights are broad: no compact emitter.
  for (const auto& file : test::real_envmap_files()) {
    const auto map = test::real_map(file);
    const SunExtraction e = extract_sun(*map, SunParams{});
    const bool sunny =
        file.rfind("city", 0) == 0 || file.rfind("forest", 0) == 0 || file.rfind("sunrise", 0) == 0;
    EXPECT_EQ(e.sun.has_value(), sunny) << file << ": " << e.reason;
    if (!e.sun) continue;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(e.residual_power[c] + e.sun->power[c], e.map_power[c]) << file;
    // The peak took the ring's mean radiance; the brightest pixel left is elsewhere and far dimmer.
    const Rgb at_peak = e.residual->image().at(e.sun->peak.x, e.sun->peak.y);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(at_peak[c], float(e.sun->fill[c])) << file;
    const float peak = luminance(map->image().at(e.sun->peak.x, e.sun->peak.y), kSunLuminance);
    const float left = e.residual->max_luminance(kSunLuminance);
    EXPECT_LT(left, 0.15f * peak) << file;
    std::printf(
        "%s: sun at pixel (%d, %d), radius %.2f deg, %.1f%% of the power, %lld pixels removed, "
        "brightest pixel %.4g of the peak's luminance left\n",
        file.c_str(), e.sun->pixel.x, e.sun->pixel.y, e.sun->angular_radius * 180 / kPi, 100 * e.sun->share,
        static_cast<long long>(e.sun->removed_pixels), double(left / peak));
  }
}

TEST(SunExtraction, IsCachedOnTheMapWithItsResidualsBytes) {
  Image image = test::latlong_image(256, test::smooth_sky);
  test::add_sun(image, 40, 10, 2, Rgb{3000, 3000, 3000});
  const MemoryBudget budget(int64_t{1} << 30);
  auto owned = std::make_shared<EnvMap>(std::move(image));
  owned->account_memory(budget, budget.reserve(EnvMap::image_bytes(256, 128), MemoryUse::Held, "the map"));
  const std::shared_ptr<const EnvMap> map = owned;
  const int64_t before = budget.used();
  bool cached = true;
  const SunExtraction first = extract_sun(*map, SunParams{}, &cached);
  ASSERT_TRUE(first.sun);
  EXPECT_FALSE(cached);
  EXPECT_GE(budget.used() - before, EnvMap::image_bytes(256, 128));  // the residual, and the weight table
  const SunExtraction again = extract_sun(*map, SunParams{}, &cached);
  EXPECT_TRUE(cached);
  EXPECT_EQ(again.residual, first.residual);
  // The residual's own derived data reserves from the same budget.
  const int64_t with_residual = budget.used();
  first.residual->sampler(kSunLuminance);
  EXPECT_GT(budget.used(), with_residual);
  SunParams other;
  other.threshold = 0.5;
  EXPECT_NE(extract_sun(*map, other).residual, first.residual);
}

TEST(SunExtraction, ParametersAreChecked) {
  SunParams p;
  p.max_radius_deg = 40;
  const EnvMap map(test::latlong_image(64, test::smooth_sky));
  try {
    extract_sun(map, p);
    FAIL() << "accepted max_radius_deg 40";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "max_radius_deg");
  }
}

}  // namespace
}  // namespace lp

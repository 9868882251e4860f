// Turntable cameras (turntable.hpp): frames evenly around +z, the elevation's swing, the camera-to-world
// matrix in Blender's convention, and the frame-count and elevation checks.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/render/scene_view.hpp"
#include "engine/render/turntable.hpp"

namespace lp::render {
namespace {

TEST(Turntable, FramesGoEvenlyRoundOnce) {
  Turntable t;
  t.frames = 4;
  t.azimuth_start_deg = 10;
  const float expected[] = {10, 100, -170, -80};  // 190 and 280 wrap into (-180, 180]
  for (int i = 0; i < 4; ++i) {
    const CameraFit fit = turntable_fit(t, i);
    EXPECT_NEAR(fit.azimuth_deg, expected[i], 1e-4f) << i;
    EXPECT_FLOAT_EQ(fit.elevation_deg, 15.0f);
    EXPECT_FLOAT_EQ(fit.margin, t.margin);
  }
  t.azimuth_step_deg = 5;
  EXPECT_NEAR(turntable_fit(t, 3).azimuth_deg, 25.0f, 1e-4f);
}

TEST(Turntable, TheElevationRisesAndFallsOncePerTurn) {
  Turntable t;
  t.frames = 8;
  t.elevation_deg = 20;
  t.elevation_sweep_deg = 10;
  EXPECT_NEAR(turntable_fit(t, 0).elevation_deg, 20.0f, 1e-5f);
  EXPECT_NEAR(turntable_fit(t, 2).elevation_deg, 30.0f, 1e-5f);
  EXPECT_NEAR(turntable_fit(t, 4).elevation_deg, 20.0f, 1e-4f);
  EXPECT_NEAR(turntable_fit(t, 6).elevation_deg, 10.0f, 1e-5f);
}

TEST(Turntable, TheMatrixLooksDownLocalMinusZWithPlusYUp) {
  // A framed camera from azimuth 90 (+x), level: it looks along -x, world +z up.
  CameraFit fit;
  fit.azimuth_deg = 90;
  fit.elevation_deg = 0;
  const Camera c = fit_camera(fit, BoundingSphere{{0, 0, 1}, 1}, 40, 1);
  const auto m = camera_to_world(c);
  const Vec3 forward{-m[2], -m[6], -m[10]}, up{m[1], m[5], m[9]}, right{m[0], m[4], m[8]};
  EXPECT_NEAR(forward.x, -1.0f, 1e-5f);
  EXPECT_NEAR(up.z, 1.0f, 1e-5f);
  EXPECT_NEAR(right.y, 1.0f, 1e-5f);  // looking along -x with +z up, +y is to the right
  EXPECT_FLOAT_EQ(m[3], c.position.x);
  EXPECT_FLOAT_EQ(m[7], c.position.y);
  EXPECT_FLOAT_EQ(m[11], c.position.z);
  EXPECT_EQ(m[15], 1.0f);
}

TEST(Turntable, ValidateNamesTheFieldOutOfRange) {
  const auto field_of = [](const Turntable& t) {
    try {
      t.validate("turntable");
    } catch (const Error& e) {
      return e.field();
    }
    return std::string();
  };
  Turntable t;
  EXPECT_EQ(field_of(t), "");
  t.frames = 0;
  EXPECT_EQ(field_of(t), "turntable.frames");
  t.frames = 36;
  t.elevation_deg = 80;
  t.elevation_sweep_deg = 20;
  EXPECT_EQ(field_of(t), "turntable.elevation_sweep_deg");
}

}  // namespace
}  // namespace lp::render

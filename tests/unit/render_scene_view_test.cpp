// Framing (scene_view.hpp): the fitted camera's distance makes the bounding sphere's silhouette meet the
// image's nearer edges times the margin; the framing sphere holds every placed vertex; the view's warnings.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/render/scene_view.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

float degrees(float radians) {
  return radians * 180 / kPiF;
}

// The angle between the view direction and the sphere's silhouette, as seen from the camera.
float silhouette_deg(const Camera& c, const BoundingSphere& s) {
  return degrees(std::asin(s.radius / length(s.center - c.position)));
}

TEST(SceneView, AFittedSphereMeetsTheNearerEdgesOfTheImage) {
  const BoundingSphere sphere{{1, 2, 3}, 2};
  CameraFit fit;
  fit.elevation_deg = 0;
  fit.margin = 1;
  // Square and wide images: the vertical field (40 degrees) binds; the sphere spans it exactly.
  for (float aspect : {1.0f, 2.0f}) {
    const Camera c = fit_camera(fit, sphere, 40, aspect);
    EXPECT_NEAR(silhouette_deg(c, sphere), 20.0f, 1e-4f);
    EXPECT_NEAR(c.position.x, 1.0f, 1e-5f);  // azimuth 0: straight in front, on -y
    EXPECT_LT(c.position.y, 2.0f);
    EXPECT_NEAR(c.position.z, 3.0f, 1e-5f);
    EXPECT_EQ(c.look_at, sphere.center);
  }
  // A tall image: the horizontal field binds, atan(tan(20 deg) * 0.5) either side.
  const Camera tall = fit_camera(fit, sphere, 40, 0.5f);
  EXPECT_NEAR(silhouette_deg(tall, sphere), degrees(std::atan(std::tan(20 * kPiF / 180) * 0.5f)), 1e-4f);
  // A margin of 2 makes the sphere half as wide: sin of its half-angle halves.
  fit.margin = 2;
  EXPECT_NEAR(std::sin(silhouette_deg(fit_camera(fit, sphere, 40, 1), sphere) * kPiF / 180),
              0.5f * std::sin(20 * kPiF / 180), 1e-5f);
}

TEST(SceneView, AzimuthTurnsAboutZFromTheFrontAndElevationRaises) {
  const BoundingSphere sphere{{0, 0, 0}, 1};
  CameraFit fit;
  fit.azimuth_deg = 90;
  fit.elevation_deg = 30;
  const Camera c = fit_camera(fit, sphere, 40, 1);
  const float d = length(c.position);
  EXPECT_NEAR(c.position.x, d * std::cos(30 * kPiF / 180), 1e-4f);  // 90: from +x
  EXPECT_NEAR(c.position.y, 0.0f, 1e-4f);
  EXPECT_NEAR(c.position.z, d * 0.5f, 1e-4f);
  EXPECT_EQ(c.up, (Vec3{0, 0, 1}));
}

TEST(SceneView, TheFramingSphereHoldsEveryPlacedVertexAndSphere) {
  SceneDesc scene;
  MeshObject quad;  // tests/data/models/obj/quad.obj: (0..1)^2 in z = 0, read y-up: y = 0, z in 0..1
  quad.path = test::model_path("obj/quad.obj");
  scene.objects.push_back({quad, {}});
  load_missing_models(scene, {});
  const BoundingSphere one = framing_sphere(scene, std::nullopt);
  EXPECT_NEAR(one.center.x, 0.5f, 1e-6f);
  EXPECT_NEAR(one.center.y, 0.0f, 1e-6f);
  EXPECT_NEAR(one.center.z, 0.5f, 1e-6f);
  EXPECT_NEAR(one.radius, std::sqrt(0.5f), 1e-6f);
  scene.objects.push_back({SphereObject{{4, 0, 0.5f}, 1}, {}});
  scene.objects.push_back({PlaneObject{{0, 0, -100}, {0, 0, 1}}, {}});  // unbounded: not framed
  const BoundingSphere both = framing_sphere(scene, std::nullopt);
  EXPECT_NEAR(both.center.x, 2.5f, 1e-6f);  // bounds x from 0 to 5
  EXPECT_NEAR(both.radius, std::sqrt(6.5f), 1e-5f);  // the quad's corners (0, 0, 0) and (0, 0, 1)
  const BoundingSphere second = framing_sphere(scene, 1);
  EXPECT_EQ(second.center, (Vec3{4, 0, 0.5f}));
  EXPECT_FLOAT_EQ(second.radius, 1.0f);
}

TEST(SceneView, WarningsNameACameraInsideAnObjectAndAViewOfNothing) {
  SceneDesc scene;
  scene.objects.push_back({SphereObject{{0, 0, 0}, 1}, {}});
  scene.camera.position = {0, 0, 0.5f};
  scene.camera.look_at = {0, 1, 0.5f};
  EXPECT_EQ(resolve_view(scene, 1).warnings,
            (std::vector<std::string>{"the camera is inside scene.objects[0] (a sphere)"}));
  scene.camera.position = {0, -4, 0};
  scene.camera.look_at = {0, -5, 0};
  EXPECT_EQ(resolve_view(scene, 1).warnings,
            (std::vector<std::string>{
                "the camera's view holds none of the scene's objects: the image shows only the map"}));
  // 45 degrees off the sphere's centre: its edge (asin(1/4) = 14.5 degrees) is 30.5 degrees from the
  // view's axis, past the image's corner (atan(tan 20 * sqrt 2) = 27.2 degrees).
  scene.camera.look_at = {1, -3, 0};
  EXPECT_EQ(resolve_view(scene, 1).warnings.size(), 1u);
  scene.camera.look_at = {0.75f, -3, 0};  // 36.9 degrees off: its edge is 22.4 degrees off, in a corner
  EXPECT_TRUE(resolve_view(scene, 1).warnings.empty());
  scene.objects.push_back({PlaneObject{{0, 0, -1}, {0, 0, 1}}, {}});
  scene.camera.look_at = {0, -5, 0};
  EXPECT_TRUE(resolve_view(scene, 1).warnings.empty()) << "a plane may be in view: not judged";
}

TEST(SceneView, AFitNeedsSomethingToFrame) {
  SceneDesc scene;
  scene.objects.push_back({PlaneObject{{0, 0, 0}, {0, 0, 1}}, {}});
  scene.camera.fit = CameraFit{};
  try {
    resolve_view(scene, 1);
    ADD_FAILURE() << "framed a plane";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "scene.camera.fit");
    EXPECT_EQ(e.problem(), "the scene has no sphere or mesh to frame");
  }
}

}  // namespace
}  // namespace lp::render

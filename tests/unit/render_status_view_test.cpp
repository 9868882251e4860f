// A render's status reports the camera as resolved and the view's warnings (api/render_schema.hpp).
#include <gtest/gtest.h>

#include "api/render_schema.hpp"

namespace lp::api {
namespace {

TEST(RenderStatusView, TheResolvedCameraAndTheWarningsAreReported) {
  RenderRequest request;
  Json before;
  describe_render(before, request, {});
  EXPECT_FALSE(before.contains("camera")) << "a request not yet resolved says nothing of its view";
  render::SceneView view;
  view.camera.position = {1, -5, 2};
  view.camera.look_at = {1, 0, 2};
  view.camera.fov_deg = 30;
  view.warnings = {"the camera is inside scene.objects[0] (a sphere)"};
  request.view = view;
  Json out;
  describe_render(out, request, {});
  EXPECT_EQ(out["camera"]["position"], Json::array({1.0, -5.0, 2.0}));
  EXPECT_EQ(out["camera"]["look_at"], Json::array({1.0, 0.0, 2.0}));
  EXPECT_EQ(out["camera"]["up"], Json::array({0.0, 0.0, 1.0}));
  EXPECT_EQ(out["camera"]["fov_deg"], 30.0);
  EXPECT_EQ(out["warnings"], Json::array({"the camera is inside scene.objects[0] (a sphere)"}));
}

}  // namespace
}  // namespace lp::api

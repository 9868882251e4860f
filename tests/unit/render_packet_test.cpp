// Camera rays traced as packets (EmbreeScene::intersect_packet) against the same rays traced one by
// one: the same objects, distances and normals, whole packets and partial ones; and a ray's result
// does not depend on the other rays of its packet.
#include <gtest/gtest.h>

#include <vector>

#include "engine/core/rng.hpp"
#include "engine/render/camera.hpp"
#include "engine/render/embree_scene.hpp"

namespace lp::render {
namespace {

// Camera rays through random points of a 64 x 64 image of the materials preset: spheres, their
// silhouettes, the plane and the sky.
std::vector<Ray> camera_rays(const SceneDesc& scene, int n) {
  const PerspectiveCamera camera(scene.camera, 64, 64);
  Rng rng(5, 6);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i)
    rays.push_back(camera.generate(64 * rng.uniform_float(), 64 * rng.uniform_float()));
  return rays;
}

TEST(RenderPacket, PacketsHitWhatSingleRaysHit) {
  const SceneDesc scene = *scene_preset("materials");
  const EmbreeScene geometry(scene, {});
  const std::vector<Ray> rays = camera_rays(scene, 4000);
  int hits = 0, disagree = 0;
  for (size_t start = 0, n = 1; start < rays.size(); start += n, n = n % EmbreeScene::kPacket + 1) {
    const size_t count = std::min(n, rays.size() - start);
    std::optional<SurfaceHit> packet[EmbreeScene::kPacket];
    geometry.intersect_packet({&rays[start], count}, {packet, count});
    for (size_t k = 0; k < count; ++k) {
      const std::optional<SurfaceHit> single = geometry.intersect(rays[start + k]);
      if (single.has_value() != packet[k].has_value()) {
        ++disagree;  // a ray grazing a silhouette, on either side of it by rounding
        continue;
      }
      if (!single) continue;
      ++hits;
      EXPECT_EQ(packet[k]->object, single->object);
      EXPECT_NEAR(packet[k]->t, single->t, 1e-4f * single->t);
      EXPECT_NEAR(dot(packet[k]->normal, single->normal), 1.0f, 1e-5f);
      EXPECT_NEAR(length(packet[k]->position - single->position), 0.0f, 1e-4f);
    }
  }
  EXPECT_GT(hits, 2000);
  EXPECT_LE(disagree, 2);
}

TEST(RenderPacket, ARaysResultDoesNotDependOnItsNeighbours) {
  const SceneDesc scene = *scene_preset("materials");
  const EmbreeScene geometry(scene, {});
  const std::vector<Ray> rays = camera_rays(scene, 800);
  for (size_t start = 0; start + EmbreeScene::kPacket <= rays.size(); start += EmbreeScene::kPacket) {
    std::optional<SurfaceHit> full[EmbreeScene::kPacket];
    geometry.intersect_packet({&rays[start], size_t(EmbreeScene::kPacket)}, full);
    for (size_t k = 0; k < size_t(EmbreeScene::kPacket); ++k) {
      std::optional<SurfaceHit> alone[1];
      geometry.intersect_packet({&rays[start + k], 1}, alone);
      ASSERT_EQ(alone[0].has_value(), full[k].has_value());
      if (alone[0]) {
        EXPECT_EQ(alone[0]->t, full[k]->t);
        EXPECT_EQ(alone[0]->object, full[k]->object);
      }
    }
  }
}

}  // namespace
}  // namespace lp::render

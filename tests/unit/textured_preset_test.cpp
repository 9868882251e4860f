// The generated model of the `textured` preset: its triangles and materials, a normal map of unit
// normals, flat on the bricks' faces and tilted on the sides of the mortar grooves, tangents
// perpendicular to the normals, and the scene the preset names.
#include "engine/render/textured_preset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "engine/render/scene_desc.hpp"

namespace lp::render {
namespace {

TEST(TexturedPreset, TheModelHasASphereOnAGroundWithTheirTextures) {
  const auto model = textured_preset_model();
  ASSERT_EQ(model->materials.size(), 2u);
  EXPECT_EQ(model->triangle_count(), model->triangle_materials.size());
  EXPECT_GT(model->triangle_count(), 1000u);
  const ModelMaterial& bricks = model->materials[0];
  ASSERT_TRUE(bricks.base_color && bricks.normal);
  EXPECT_EQ(bricks.normal->texture->width(), kBrickTextureWidth);
  EXPECT_EQ(bricks.normal->texture->height(), kBrickTextureHeight);
  const ModelMaterial& ground = model->materials[1];
  ASSERT_TRUE(ground.base_color);
  EXPECT_FALSE(ground.normal);
  EXPECT_EQ(ground.base_color->transform.scale.x, 6.0f);
  EXPECT_EQ(textured_preset_model(), model);  // built once
}

TEST(TexturedPreset, TheNormalMapHoldsUnitNormalsFlatOnTheBricks) {
  const Texture& map = *textured_preset_model()->materials[0].normal->texture;
  int flat = 0, tilted = 0;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const Rgba t = map.texel(0, x, y);
      const Vec3 n{2 * t.r - 1, 2 * t.g - 1, 2 * t.b - 1};
      ASSERT_NEAR(length(n), 1.0f, 1e-5f) << x << ", " << y;
      ASSERT_GT(n.z, 0.5f);
      (n.z > 1 - 1e-6f ? flat : tilted)++;
    }
  EXPECT_GT(flat, map.width() * map.height() / 4);     // the brick faces and the grooves' floors
  EXPECT_GT(tilted, map.width() * map.height() / 20);  // the mortar grooves' sides
}

TEST(TexturedPreset, TangentsArePerpendicularUnitVectors) {
  const auto model = textured_preset_model();
  ASSERT_EQ(model->tangents.size(), model->vertex_count());
  for (size_t i = 0; i < model->vertex_count(); ++i) {
    EXPECT_NEAR(length(model->tangents[i].direction), 1.0f, 1e-4f) << i;
    EXPECT_NEAR(dot(model->tangents[i].direction, model->normals[i]), 0.0f, 1e-4f) << i;
  }
}

TEST(TexturedPreset, ThePresetSceneHoldsTheModel) {
  const SceneDesc scene = preset_scene(ScenePreset::Textured);
  ASSERT_EQ(scene.objects.size(), 1u);
  const auto& mesh = std::get<MeshObject>(scene.objects[0].shape);
  EXPECT_EQ(mesh.model, textured_preset_model());
  scene.validate("scene");
}

}  // namespace
}  // namespace lp::render

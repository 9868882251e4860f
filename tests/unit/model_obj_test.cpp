// OBJ/MTL models: Kd, Ns, map_Kd, map_Bump/norm, Ke and texture options mapped onto metallic-roughness
// materials, texture coordinates flipped to glTF's convention, and malformed input refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

TEST(ObjModel, MaterialsTexturesAndFlippedTextureCoordinates) {
  const Model m = load_model(test::model_path("obj/quad.obj"), {});
  ASSERT_EQ(m.triangle_count(), 2u);
  EXPECT_EQ(m.vertex_count(), 4u);  // shared (v, vt, vn) triples are one vertex
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.triangle_materials[0], 0u);
  EXPECT_EQ(m.triangle_materials[1], 1u);
  // vt (0, 0) at the bottom-left corner is glTF's (0, 1).
  EXPECT_EQ(m.positions[0], (Vec3{0, 0, 0}));
  EXPECT_FLOAT_EQ(m.uvs[0].y, 1.0f);
  EXPECT_NEAR(m.tangents[0].direction.x, 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(m.tangents[0].w, 1.0f);

  const ModelMaterial& textured = m.materials[0];
  EXPECT_EQ(textured.name, "textured");
  EXPECT_FLOAT_EQ(textured.metallic_factor, 0.0f);
  EXPECT_NEAR(textured.roughness_factor, std::pow(2.0f / 12.0f, 0.25f), 1e-6f);  // Ns 10
  ASSERT_TRUE(textured.base_color && textured.normal);
  EXPECT_EQ(textured.base_color->sampler.wrap_s, WrapMode::ClampToEdge);  // -clamp on
  EXPECT_TRUE(textured.base_color->transform.identity());                 // no -o, -s: v' = v
  EXPECT_FLOAT_EQ(textured.normal_scale, 0.5f);                           // -bm 0.5
  EXPECT_FLOAT_EQ(textured.base_color->texture->texel(0, 1, 0).g, 1.0f);  // green, top right

  const ModelMaterial& plain = m.materials[1];
  EXPECT_FLOAT_EQ(plain.base_color_factor.g, 0.25f);
  EXPECT_FLOAT_EQ(plain.roughness_factor, 1.0f);  // Ns 0
  EXPECT_FLOAT_EQ(plain.emissive_factor.x, 0.5f);
  EXPECT_FALSE(plain.base_color.has_value());
}

TEST(ObjModel, WithoutTextureCoordinatesOrNormals) {
  const Model m = load_obj_memory("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n",
                                  "newmtl a\nKd 1 1 1\n", "t.obj", {});
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.uvs[0].x + m.uvs[0].y, 0.0f);  // no vt: (0, 0)
  EXPECT_EQ(m.normals[0], (Vec3{0, 0, 1}));  // no vn: flat
}

TEST(ObjModel, OffsetAndScaleOptionsBecomeATransformInGltfCoordinates) {
  const auto dir = std::filesystem::temp_directory_path() / "lightprobe_obj_options";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(test::model_path("obj/checker.png"), dir / "c.png",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "m.obj")
      << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl a\nf 1/1 2/1 3/1\n";
  std::ofstream(dir / "m.mtl") << "newmtl a\nmap_Kd -o 0.25 0.5 0 -s 2 3 1 c.png\n";
  const Model m = load_model(dir / "m.obj", {});
  const TextureTransform& t = m.materials[0].base_color->transform;
  // OBJ (u, v) -> (2u + 0.25, 3v + 0.5); in glTF's v' = 1 - v that is v' -> 3v' + (1 - 3 - 0.5).
  EXPECT_FLOAT_EQ(t.scale.x, 2.0f);
  EXPECT_FLOAT_EQ(t.scale.y, 3.0f);
  EXPECT_FLOAT_EQ(t.offset.x, 0.25f);
  EXPECT_FLOAT_EQ(t.offset.y, -2.5f);
  const Point2 obj{0.1f, 0.2f}, gltf = t.apply({obj.x, 1.0f - obj.y});
  EXPECT_NEAR(gltf.x, 2 * obj.x + 0.25f, 1e-6f);
  EXPECT_NEAR(1.0f - gltf.y, 3 * obj.y + 0.5f, 1e-6f);
  std::filesystem::remove_all(dir);
}

TEST(ObjModel, FacesWithoutAMaterialGetTheDefaultOne) {
  const Model m = load_obj_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n", "", "t.obj", {});
  EXPECT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "default");
  EXPECT_FLOAT_EQ(m.materials[0].metallic_factor, 0.0f);
}

TEST(ObjModel, MalformedInputIsRefused) {
  const auto kind = [](const std::string& obj, const std::string& mtl, const ModelLimits& limits = {}) {
    try {
      load_obj_memory(obj, mtl, "bad.obj", limits);
    } catch (const Error& e) {
      return e.kind();
    }
    return ErrorKind::Internal;
  };
  EXPECT_EQ(kind("v 0 0 0\nf 1 2 3\n", ""), ErrorKind::Corrupt);  // missing vertices
  EXPECT_EQ(kind("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/5 2/1 3/1\n", ""),
            ErrorKind::Corrupt);  // missing vt
  EXPECT_EQ(kind("v 1e99999 0 0\n", ""), ErrorKind::Corrupt);
  EXPECT_EQ(kind("v 0 0 0\n", ""), ErrorKind::Corrupt);  // no triangles
  EXPECT_EQ(kind("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "newmtl a\nNs 1e2147483648\n"),
            ErrorKind::Corrupt);
  EXPECT_EQ(kind("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "newmtl a\nillum 99999999999\n"),
            ErrorKind::Corrupt);
  EXPECT_EQ(
      kind("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n", "newmtl a\nmap_Kd tex.png\n"),
      ErrorKind::InvalidArgument);  // from memory: no texture files
  ModelLimits one;
  one.max_triangles = 1;
  EXPECT_EQ(kind("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n", "", one), ErrorKind::TooLarge);
}

}  // namespace
}  // namespace lp

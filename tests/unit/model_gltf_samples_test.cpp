// Every glTF sample of Debian's assimp-testmodels: the valid ones load with their triangle counts, the
// broken ones (and the ones using what we do not read) are refused with an lp::Error; none crashes.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"

namespace lp {
namespace {

const std::filesystem::path kSamples = "/usr/share/assimp/models/glTF2";

// Valid files and the triangles their default scene holds. Every other sample must be refused.
const std::map<std::string, size_t> kValid = {
    {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496},
    {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12},
    {"BoxTextured-glTF-Binary/BoxTextured.glb", 12},
    {"BoxTextured-glTF-Embedded/BoxTextured.gltf", 12},
    {"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12},
    {"BoxTextured-glTF/BoxTextured.gltf", 12},
    {"ClearCoat-glTF/ClearCoatTest.gltf", 37116},
    {"cameras/Cameras.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 2},  // triangle strip
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 2},  // triangle fan
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_11.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf", 2},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_15.gltf", 2},
    {"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12},
    {"issue_3269/texcoord_crash.gltf", 10},
    {"simple_skin/simple_skin.gltf", 8},
    {"textureTransform/TextureTransformTest.gltf", 24},
};

// Refused files and the kind of error: malformed ones Corrupt, a missing buffer NotFound, extensions
// and texture coordinate sets we do not read Unsupported.
const std::map<std::string, ErrorKind> kRefused = {
    {"BoxTexcoords-glTF/boxTexcoords.gltf", ErrorKind::Unsupported},               // TEXCOORD_1
    {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", ErrorKind::Unsupported},  // required extension
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", ErrorKind::Corrupt},
    {"IncorrectVertexArrays/Cube.gltf", ErrorKind::Corrupt},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf", ErrorKind::Corrupt},
    {"IndexOutOfRange/IndexOutOfRange.gltf", ErrorKind::Corrupt},
    {"MissingBin/BoxTextured.gltf", ErrorKind::NotFound},
    {"RecursiveNodes/RecursiveNodes.gltf", ErrorKind::Corrupt},
    {"SchemaFailures/sceneWrongType.gltf", ErrorKind::Corrupt},
    {"TestNoRootNode/NoScene.gltf", ErrorKind::Corrupt},
    {"TestNoRootNode/SceneWithoutNodes.gltf", ErrorKind::Corrupt},
    {"draco/2CylinderEngine.gltf",
     ErrorKind::Corrupt},  // Draco-compressed: its accessors have no buffer view
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf",
     ErrorKind::Corrupt},  // points only
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf", ErrorKind::Corrupt},  // lines only
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", ErrorKind::Corrupt},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", ErrorKind::Corrupt},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", ErrorKind::Corrupt},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", ErrorKind::Corrupt},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", ErrorKind::Corrupt},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badArray.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badExtension.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badNumber.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badObject.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badString.gltf", ErrorKind::Corrupt},
    {"wrongTypes/badUint.gltf", ErrorKind::Corrupt},
};

TEST(GltfSamples, EverySampleLoadsWithItsTriangleCountOrIsRefused) {
  size_t seen = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kSamples)) {
    const auto ext = entry.path().extension();
    if (ext != ".gltf" && ext != ".glb") continue;
    ++seen;
    const std::string name = entry.path().lexically_relative(kSamples).string();
    SCOPED_TRACE(name);
    if (const auto valid = kValid.find(name); valid != kValid.end()) {
      const Model m = load_model(entry.path(), {});
      EXPECT_EQ(m.triangle_count(), valid->second);
      EXPECT_EQ(m.triangle_materials.size(), m.triangle_count());
      EXPECT_EQ(m.normals.size(), m.vertex_count());
      EXPECT_EQ(m.uvs.size(), m.vertex_count());
      EXPECT_EQ(m.tangents.size(), m.vertex_count());
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
      for (uint32_t mat : m.triangle_materials) ASSERT_LT(mat, m.materials.size());
      for (const Vec3& n : m.normals) ASSERT_NEAR(length(n), 1.0f, 1e-4f);
      continue;
    }
    const auto refused = kRefused.find(name);
    ASSERT_NE(refused, kRefused.end()) << "a sample this test does not know";
    try {
      load_model(entry.path(), {});
      ADD_FAILURE() << "loaded";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), refused->second) << e.what();
      EXPECT_LT(std::string(e.what()).size(), 700u);
    }
  }
  EXPECT_EQ(seen, kValid.size() + kRefused.size());
}

TEST(GltfSamples, BoxTexturedHasTwelveTrianglesWithItsTextureCoordinatesAndSampler) {
  // The .gltf's sampler mirrors along s and clamps along t; the other two variants repeat.
  const std::pair<const char*, TextureSampler> files[] = {
      {"BoxTextured-glTF/BoxTextured.gltf", {WrapMode::MirroredRepeat, WrapMode::ClampToEdge}},
      {"BoxTextured-glTF-Binary/BoxTextured.glb", {}},
      {"BoxTextured-glTF-Embedded/BoxTextured.gltf", {}}};
  for (const auto& [file, sampler] : files) {
    SCOPED_TRACE(file);
    const Model m = load_model(kSamples / file, {});
    ASSERT_EQ(m.triangle_count(), 12u);
    ASSERT_EQ(m.vertex_count(), 24u);
    // The first vertices as stored in the file (UVs past 1 rely on the sampler's wrapping).
    EXPECT_FLOAT_EQ(m.uvs[0].x, 6.0f);
    EXPECT_FLOAT_EQ(m.uvs[0].y, 0.0f);
    EXPECT_FLOAT_EQ(m.uvs[1].x, 5.0f);
    EXPECT_NEAR(m.uvs[2].y, 1.0f, 1e-6f);
    EXPECT_EQ(m.indices[3], 3u);
    // The root node's matrix turns (x, y, z) into (x, z, -y): (-0.5, -0.5, 0.5) -> (-0.5, 0.5, 0.5).
    EXPECT_NEAR(m.positions[0].x, -0.5f, 1e-6f);
    EXPECT_NEAR(m.positions[0].y, 0.5f, 1e-6f);
    EXPECT_NEAR(m.positions[0].z, 0.5f, 1e-6f);
    ASSERT_EQ(m.materials.size(), 1u);
    const ModelMaterial& mat = m.materials[0];
    EXPECT_FLOAT_EQ(mat.metallic_factor, 0.0f);
    EXPECT_FLOAT_EQ(mat.roughness_factor, 1.0f);
    ASSERT_TRUE(mat.base_color.has_value());
    EXPECT_EQ(mat.base_color->texture->width(), 211);
    EXPECT_EQ(mat.base_color->sampler, sampler);
    EXPECT_FALSE(mat.normal.has_value());
  }
}

TEST(GltfSamples, TextureTransformTestReadsOffsetRotationAndScale) {
  const Model m = load_model(kSamples / "textureTransform/TextureTransformTest.gltf", {});
  ASSERT_EQ(m.materials.size(), 9u);
  std::map<std::string, TextureTransform> by_name;
  for (const ModelMaterial& mat : m.materials) by_name[mat.name] = mat.base_color->transform;
  EXPECT_FLOAT_EQ(by_name["Offset V"].offset.y, 0.5f);
  EXPECT_FLOAT_EQ(by_name["Rotation"].rotation, 0.39269908169872414f);
  const TextureTransform& all = by_name["All"];
  EXPECT_FLOAT_EQ(all.offset.x, -0.2f);
  EXPECT_FLOAT_EQ(all.offset.y, -0.1f);
  EXPECT_FLOAT_EQ(all.rotation, 0.3f);
  EXPECT_FLOAT_EQ(all.scale.x, 1.5f);
  EXPECT_TRUE(by_name["Correct"].identity());
}

}  // namespace
}  // namespace lp

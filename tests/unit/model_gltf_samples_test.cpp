// Every glTF sample of Debian's assimp-testmodels (support/gltf_samples.hpp): the valid ones load with
// their triangle counts, the broken ones (and glTF 1.0, and what we do not read) are refused with an
// lp::Error; none crashes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "support/gltf_samples.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

const std::filesystem::path kSamples = test::assimp_model_path("glTF2");

TEST(GltfSamples, EverySampleLoadsWithItsTriangleCountOrIsRefused) {
  const auto& valid = test::valid_gltf_samples();
  const auto& refused = test::refused_gltf_samples();
  const std::vector<std::string> files = test::gltf_sample_files();
  for (const std::string& name : files) {
    SCOPED_TRACE(name);
    const std::filesystem::path path = test::assimp_model_path(name);
    if (const auto v = valid.find(name); v != valid.end()) {
      const Model m = load_model(path, {});
      EXPECT_EQ(m.triangle_count(), v->second);
      EXPECT_EQ(m.triangle_materials.size(), m.triangle_count());
      EXPECT_EQ(m.normals.size(), m.vertex_count());
      EXPECT_EQ(m.uvs.size(), m.vertex_count());
      EXPECT_EQ(m.tangents.size(), m.vertex_count());
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
      for (uint32_t mat : m.triangle_materials) ASSERT_LT(mat, m.materials.size());
      for (const Vec3& n : m.normals) ASSERT_NEAR(length(n), 1.0f, 1e-4f);
      continue;
    }
    const auto r = refused.find(name);
    ASSERT_NE(r, refused.end()) << "a sample this test does not know";
    try {
      load_model(path, {});
      ADD_FAILURE() << "loaded";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), r->second) << e.what();
      EXPECT_LT(std::string(e.what()).size(), 700u);
      // glTF 1.0 is refused as such, not for the first property whose type 2.0 changed.
      if (name.starts_with("glTF/")) {
        EXPECT_NE(std::string(e.what()).find("glTF 1.0"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_EQ(files.size(), valid.size() + refused.size());
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
    // Each face is four vertices (a parallelogram: corner 3 = 1 + 2 - 0) whose UVs are an affine map
    // onto a unit square [k, k + 1] x [0, 1], a different k = 0..5 per face: the box unrolled along u.
    std::set<int> squares;
    for (size_t f = 0; f < 6; ++f) {
      const size_t v = f * 4;
      const Vec3 p = m.positions[v + 1] + m.positions[v + 2] - m.positions[v];
      EXPECT_NEAR(length(p - m.positions[v + 3]), 0.0f, 1e-6f) << "face " << f;
      const Point2 uv0 = m.uvs[v], uv1 = m.uvs[v + 1], uv2 = m.uvs[v + 2], uv3 = m.uvs[v + 3];
      EXPECT_NEAR(uv1.x + uv2.x - uv0.x, uv3.x, 1e-6f) << "face " << f;
      EXPECT_NEAR(uv1.y + uv2.y - uv0.y, uv3.y, 1e-6f) << "face " << f;
      const float u_min = std::min({uv0.x, uv1.x, uv2.x, uv3.x}),
                  u_max = std::max({uv0.x, uv1.x, uv2.x, uv3.x});
      const float v_min = std::min({uv0.y, uv1.y, uv2.y, uv3.y}),
                  v_max = std::max({uv0.y, uv1.y, uv2.y, uv3.y});
      EXPECT_FLOAT_EQ(u_min, std::round(u_min)) << "face " << f;
      EXPECT_FLOAT_EQ(u_max - u_min, 1.0f) << "face " << f;
      EXPECT_FLOAT_EQ(v_min, 0.0f) << "face " << f;
      EXPECT_NEAR(v_max, 1.0f, 1e-6f) << "face " << f;
      squares.insert(int(u_min));
    }
    EXPECT_EQ(squares, (std::set<int>{0, 1, 2, 3, 4, 5}));
    // The root node's matrix turns (x, y, z) into (x, z, -y): (-0.5, -0.5, 0.5) -> (-0.5, 0.5, 0.5),
    // which enters the world as (x, -z, y): (-0.5, -0.5, 0.5).
    EXPECT_NEAR(m.positions[0].x, -0.5f, 1e-6f);
    EXPECT_NEAR(m.positions[0].y, -0.5f, 1e-6f);
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

// A model's description: bounds and the bounding sphere about their centre, counts, the features each
// material uses and its textures (each once, with its colour space), and from a glTF document its
// cameras, extensions and the warnings for what the loader ignores, each saying where.
#include "engine/model/model_info.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "engine/core/error.hpp"
#include "engine/model/gltf_extensions.hpp"
#include "engine/model/gltf_source.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using json = nlohmann::json;

json quad_json() {
  std::ifstream in(test::model_path("quad_embedded.gltf"));
  return json::parse(in);
}

Model load_json(const json& doc) {
  const std::string text = doc.dump();
  return load_gltf_memory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, "q.gltf", {});
}

std::shared_ptr<const Texture> texture(int width, int height) {
  return std::make_shared<Texture>(width, height, 3, std::vector<float>(size_t(width * height * 3), 0.5f));
}

TEST(ModelInfo, TheSphereIsTheSmallestAboutTheBoxCentreHoldingEveryVertex) {
  Model m;
  // The box [0, 4] x [0, 2] x [0, 6]; no vertex at a corner, the farthest sqrt(10) from its centre.
  m.positions = {{0, 0, 3}, {4, 1, 3}, {2, 0, 0}, {2, 2, 6}};
  m.indices = {0, 1, 2, 0, 2, 3};
  const ModelInfo info = describe_model(m);
  EXPECT_EQ(info.bounds.min, (Vec3{0, 0, 0}));
  EXPECT_EQ(info.bounds.max, (Vec3{4, 2, 6}));
  EXPECT_EQ(info.sphere.center, (Vec3{2, 1, 3}));
  EXPECT_FLOAT_EQ(info.sphere.radius, std::sqrt(10.0f));
  EXPECT_EQ(info.triangles, 2);
  EXPECT_EQ(info.vertices, 4);
}

TEST(ModelInfo, MaterialFeaturesAndEachTextureOnceWithItsColourSpace) {
  Model m;
  const auto albedo = texture(4, 2), data = texture(1, 1);
  ModelMaterial a;
  a.name = "a";
  a.base_color = TextureBinding{albedo, {}, {}};
  a.metallic_roughness = TextureBinding{data, {}, {}};
  a.emissive_factor = {0, 0.5f, 0};
  ModelMaterial b;
  b.name = "b";
  b.base_color = TextureBinding{albedo, {}, {}};  // shared: listed once
  b.normal = TextureBinding{data, {}, {}};
  b.emissive = TextureBinding{albedo, {}, {}};  // a texture with a zero factor: no emission
  a.alpha_mode = AlphaMode::Mask;
  b.double_sided = false;
  m.materials = {a, b};
  m.source.materials = {{{"KHR_materials_ior"}}};  // the file's, for a only
  const ModelInfo info = describe_model(m);
  ASSERT_EQ(info.materials.size(), 2u);
  EXPECT_EQ(info.materials[0].features,
            (std::vector<std::string>{"base_color_texture", "metallic_roughness_texture", "emissive",
                                      "alpha_mask", "double_sided"}));
  EXPECT_EQ(info.materials[0].extensions, (std::vector<std::string>{"KHR_materials_ior"}));
  EXPECT_EQ(info.materials[1].features,
            (std::vector<std::string>{"base_color_texture", "normal_texture", "emissive_texture"}));
  EXPECT_TRUE(info.materials[1].extensions.empty());
  ASSERT_EQ(info.textures.size(), 2u);
  EXPECT_EQ(info.textures[0].width, 4);
  EXPECT_EQ(info.textures[0].height, 2);
  EXPECT_EQ(info.textures[0].bytes, albedo->memory_bytes());
  EXPECT_EQ(info.textures[0].color_space, ColorSpace::Srgb);
  EXPECT_EQ(info.textures[1].width, 1);
  EXPECT_EQ(info.textures[1].color_space, ColorSpace::Linear);
}

// glTF x in [1, 3], y in [2, 4], z = 3 (model_gltf_test.cpp), in the world (x, -z, y).
TEST(ModelInfo, TheQuadFromItsGlb) {
  const ModelInfo info = describe_model(load_model(test::model_path("quad.glb"), {}));
  EXPECT_EQ(info.bounds.min, (Vec3{1, -3, 2}));
  EXPECT_EQ(info.bounds.max, (Vec3{3, -3, 4}));
  EXPECT_EQ(info.sphere.center, (Vec3{2, -3, 3}));
  EXPECT_FLOAT_EQ(info.sphere.radius, std::sqrt(2.0f));
  EXPECT_EQ(info.triangles, 2);
  EXPECT_EQ(info.vertices, 4);
  EXPECT_EQ(info.meshes, 1);
  ASSERT_EQ(info.materials.size(), 1u);
  EXPECT_EQ(info.materials[0].name, "quad");
  EXPECT_EQ(info.materials[0].features,
            (std::vector<std::string>{"base_color_texture", "normal_texture", "emissive"}));
  EXPECT_EQ(info.extensions_used, (std::vector<std::string>{"KHR_texture_transform"}));
  EXPECT_TRUE(info.warnings.empty());
  EXPECT_TRUE(info.cameras.empty());
}

TEST(ModelInfo, IgnoredContentIsWarnedWhereItIs) {
  json doc = quad_json();
  doc["extensionsUsed"] = {"KHR_texture_transform", "EXT_a", "EXT_b"};
  doc["materials"][0]["normalTexture"]["extensions"]["EXT_a"] = json::object();
  doc["nodes"][1]["extensions"]["EXT_b"] = json::object();
  doc["materials"][0]["alphaMode"] = "BLEND";
  doc["materials"][0]["doubleSided"] = true;
  json points = doc["meshes"][0]["primitives"][0];
  points["mode"] = 0;
  points["targets"] = {{{"POSITION", 0}}};
  doc["meshes"][0]["primitives"].push_back(points);
  const Model m = load_json(doc);
  const ModelInfo info = describe_model(m);
  EXPECT_EQ(info.warnings, (std::vector<std::string>{
                               "materials[0].normalTexture: EXT_a is not supported and is ignored",
                               "nodes[1]: EXT_b is not supported and is ignored",
                               "meshes[0].primitives[1]: points and lines are not rendered",
                               "meshes[0].primitives[1]: morph targets are ignored",
                           }));
  EXPECT_EQ(info.materials[0].features,
            (std::vector<std::string>{"base_color_texture", "normal_texture", "emissive", "alpha_blend",
                                      "double_sided"}));
  EXPECT_EQ(info.triangles, 2);  // the points add none
}

TEST(ModelInfo, WarningsAreCappedWithACountOfTheOthers) {
  json doc = quad_json();
  doc["extensionsUsed"] = {"KHR_texture_transform", "EXT_a"};
  for (size_t i = 0; i < gltf::kMaxWarnings + 8; ++i) {
    json node = {{"extensions", {{"EXT_a", json::object()}}}};
    doc["nodes"].push_back(node);
  }
  const ModelInfo info = describe_model(load_json(doc));
  ASSERT_EQ(info.warnings.size(), gltf::kMaxWarnings + 1);
  EXPECT_EQ(info.warnings.front(), "nodes[2]: EXT_a is not supported and is ignored");
  EXPECT_EQ(info.warnings.back(), "and 8 more warnings");
}

TEST(ModelInfo, OnlyTheSupportedExtensionsMayBeRequired) {
  json doc = quad_json();
  doc["extensionsRequired"] = {"KHR_texture_transform"};
  EXPECT_EQ(describe_model(load_json(doc)).triangles, 2);
  for (std::string_view name : gltf::kSupportedExtensions) EXPECT_TRUE(gltf::is_supported_extension(name));
  doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_materials_anisotropy"};
  try {
    load_json(doc);
    ADD_FAILURE() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unsupported);
    EXPECT_NE(std::string(e.what()).find("requires the extension KHR_materials_anisotropy"),
              std::string::npos)
        << e.what();
  }
}

// An OBJ states no up axis: its bounds are those of a scene's default, y-up, (x, y, z) -> (x, -z, y).
TEST(ModelInfo, AnObjCountsItsObjectsAndHasNoGltfFacts) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\no a\nf 1 2 3\no b\nf 1 2 4\n";
  const ModelInfo info = describe_model(load_obj_memory(obj, "", "two.obj", {}));
  EXPECT_EQ(info.meshes, 2);
  EXPECT_EQ(info.triangles, 2);
  EXPECT_EQ(info.bounds.min, (Vec3{0, -1, 0}));
  EXPECT_EQ(info.bounds.max, (Vec3{1, 0, 1}));
  ASSERT_EQ(info.materials.size(), 1u);  // the default
  EXPECT_EQ(info.materials[0].features, (std::vector<std::string>{"double_sided"}));  // as it renders
  EXPECT_TRUE(info.extensions_used.empty());
  EXPECT_TRUE(info.warnings.empty());
}

}  // namespace
}  // namespace lp

// glTF loading on the committed test quad (tests/data/models): the node hierarchy's transforms,
// materials and their textures, embedded (data URI, .glb buffer views) and external files, and an
// lp::Error naming the fault for each kind of malformed input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using json = nlohmann::json;

// The quad: (0..1)^2 in z = 0 under a node translated by (1, 2, 3) whose child scales by 2, entering
// the world as glTF (x, y, z) -> (x, -z, y).
void expect_quad(const Model& m) {
  ASSERT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.positions[2], (Vec3{3, -3, 4}));  // glTF (1, 1, 0) * 2 + (1, 2, 3) = (3, 4, 3)
  EXPECT_EQ(m.normals[0], (Vec3{0, -1, 0}));    // glTF +z, the front, faces -y
  EXPECT_FLOAT_EQ(m.uvs[0].y, 1.0f);  // bottom-left corner: v = 1 (glTF's v runs down the image)
  // The tangent follows u (+x); the bitangent cross(n, t) * w points up the image (glTF +y, world +z).
  EXPECT_NEAR(m.tangents[0].direction.x, 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(m.tangents[0].w, 1.0f);
  ASSERT_EQ(m.materials.size(), 1u);
  const ModelMaterial& mat = m.materials[0];
  EXPECT_EQ(mat.name, "quad");
  EXPECT_FLOAT_EQ(mat.base_color_factor.g, 0.5f);
  EXPECT_FLOAT_EQ(mat.metallic_factor, 0.25f);
  EXPECT_FLOAT_EQ(mat.roughness_factor, 0.75f);
  EXPECT_FLOAT_EQ(mat.normal_scale, 0.5f);
  EXPECT_FLOAT_EQ(mat.emissive_factor.z, 0.3f);
  ASSERT_TRUE(mat.base_color && mat.normal);
  EXPECT_FALSE(mat.metallic_roughness || mat.emissive);
  EXPECT_EQ(mat.base_color->sampler.wrap_s, WrapMode::ClampToEdge);
  EXPECT_EQ(mat.base_color->sampler.wrap_t, WrapMode::MirroredRepeat);
  EXPECT_EQ(mat.normal->sampler.wrap_s, WrapMode::Repeat);
  EXPECT_FLOAT_EQ(mat.base_color->transform.offset.x, 0.5f);
  EXPECT_FLOAT_EQ(mat.base_color->transform.scale.x, 2.0f);
  // A footprint of 0.5 in vertex UVs is sqrt(2 * 1) wider after the transform's scale: 0.5 * sqrt(2) * 2
  // texels of the 2 x 2 level 0, log2 = 0.5.
  EXPECT_FLOAT_EQ(mat.base_color->level_for_footprint(0.5f), 0.5f);
  // 2 x 2 texture: red, green / blue, white; sRGB 255 decodes to 1.
  const Texture& t = *mat.base_color->texture;
  EXPECT_FLOAT_EQ(t.texel(0, 0, 0).r, 1.0f);
  EXPECT_FLOAT_EQ(t.texel(0, 1, 0).g, 1.0f);
  EXPECT_FLOAT_EQ(t.texel(0, 0, 1).b, 1.0f);
  EXPECT_FLOAT_EQ(mat.normal->texture->texel(0, 0, 0).r, 128 / 255.0f);  // linear
  // uv (0.2, 0.1) -> transformed (0.9, 0.1): past the green texel's centre, where clamping keeps green
  // (repeating would blend in red); the row below mirrors back to row 0.
  const Rgba c = mat.base_color->sample({0.2f, 0.1f}, 0);
  EXPECT_FLOAT_EQ(c.r, 0.0f);
  EXPECT_FLOAT_EQ(c.g, 1.0f);
}

TEST(GltfModel, EmbeddedDataUris) {
  expect_quad(load_model(test::model_path("quad_embedded.gltf"), {}));
}

TEST(GltfModel, BinaryWithImagesInBufferViews) {
  expect_quad(load_model(test::model_path("quad.glb"), {}));
}

TEST(GltfModel, ExternalBufferAndUriEncodedImageFiles) {
  expect_quad(load_model(test::model_path("gltf/quad.gltf"), {}));
}

TEST(GltfModel, FromMemoryTheSameAsFromTheFile) {
  expect_quad(load_gltf_memory(test::read_bytes(test::model_path("quad.glb")), "quad.glb", {}));
}

TEST(GltfModel, TexturesAreSharedThroughTheCache) {
  TextureCache cache;
  const Model a = load_model(test::model_path("gltf/quad.gltf"), {}, &cache);
  const Model b = load_model(test::model_path("gltf/quad.gltf"), {}, &cache);
  EXPECT_EQ(a.materials[0].base_color->texture.get(), b.materials[0].base_color->texture.get());
  EXPECT_EQ(cache.size(), 2u);  // base colour and normal map
  EXPECT_GT(a.memory_bytes(), 0);
}

json quad_json() {
  std::ifstream in(test::model_path("quad_embedded.gltf"));
  return json::parse(in);
}

// The error loading the quad after `change`, from memory.
Error error_after(const std::function<void(json&)>& change, const ModelLimits& limits = {}) {
  json doc = quad_json();
  change(doc);
  const std::string text = doc.dump();
  try {
    load_gltf_memory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, "quad.gltf", limits);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "loaded";
  return Error(ErrorKind::Internal, "loaded");
}

void expect_error(const Error& e, ErrorKind kind, const std::string& words) {
  EXPECT_EQ(e.kind(), kind) << e.what();
  EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
}

TEST(GltfModel, MalformedInputsNameTheirFault) {
  expect_error(error_after([](json& d) { d["accessors"][0]["count"] = 5; }), ErrorKind::Corrupt,
               "lie outside its buffer view");
  expect_error(error_after([](json& d) { d["accessors"][0]["componentType"] = 5123; }), ErrorKind::Corrupt,
               "component type 5123 (unsigned short) is not allowed");
  expect_error(error_after([](json& d) { d["accessors"][2]["type"] = "VEC3"; }), ErrorKind::Corrupt,
               "has 3 components per element, not 2");
  expect_error(error_after([](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 9; }),
               ErrorKind::Corrupt, "indices accessor out of bounds");
  expect_error(error_after([](json& d) { d["bufferViews"][3]["byteLength"] = 1000; }), ErrorKind::Corrupt,
               "lies outside buffer 0");
  expect_error(error_after([](json& d) { d["meshes"][0]["primitives"][0]["material"] = 4; }),
               ErrorKind::Corrupt, "material 4, which does not exist");
  expect_error(error_after([](json& d) { d["textures"][0]["source"] = 7; }), ErrorKind::Corrupt,
               "image 7, which does not exist");
  expect_error(error_after([](json& d) { d["textures"][0]["sampler"] = 3; }), ErrorKind::Corrupt,
               "sampler 3, which does not exist");
  expect_error(error_after([](json& d) { d["samplers"][0]["wrapS"] = 1234; }), ErrorKind::Corrupt,
               "unknown wrap mode 1234");
  expect_error(error_after([](json& d) { d["nodes"][1]["children"] = json::array({0}); }), ErrorKind::Corrupt,
               "node graph is recursive");
  expect_error(error_after([](json& d) { d["nodes"][0]["children"] = json::array({5}); }), ErrorKind::Corrupt,
               "node 5 does not exist");
  expect_error(error_after([](json& d) {
                 d["nodes"][1]["matrix"] = {1, 0, 0};
               }),
               ErrorKind::Corrupt, "matrix has 3 numbers, not 16");
  expect_error(error_after([](json& d) { d["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 2; }),
               ErrorKind::Corrupt, "metallicFactor 2 is not in [0, 1]");
  expect_error(error_after([](json& d) { d["materials"][0]["normalTexture"]["scale"] = "big"; }),
               ErrorKind::Corrupt, "materials[0].normalTexture.scale must be a number");
  expect_error(
      error_after([](json& d) { d["extensionsRequired"] = json::array({"KHR_draco_mesh_compression"}); }),
      ErrorKind::Unsupported, "KHR_draco_mesh_compression");
  expect_error(error_after([](json& d) { d["buffers"][0]["uri"] = "quad.bin"; }), ErrorKind::InvalidArgument,
               "cannot refer to the file 'quad.bin'");
  expect_error(error_after([](json& d) { d["images"][0]["uri"] = "data:image/png;base64,AAAA"; }),
               ErrorKind::Unsupported, "image 0 is not an image format we read");
  expect_error(error_after([](json& d) {
                 json nest = json::array();
                 for (int i = 0; i < 100; ++i) nest = json::array({nest});
                 d["extras"] = nest;
               }),
               ErrorKind::Corrupt, "nested over 64 levels");
}

TEST(GltfModel, NonFiniteValuesAreRefused) {
  // Finite in the file, beyond float in world space. (Non-finite accessor values: BoxWithInfinites.)
  expect_error(error_after([](json& d) {
                 d["nodes"][0]["translation"] = {1e308, 0, 0};
                 d["nodes"][1]["scale"] = {1e308, 1, 1};
               }),
               ErrorKind::InvalidData, "not finite");
}

TEST(GltfModel, LimitsAreCheckedBeforeAllocating) {
  ModelLimits triangles;
  triangles.max_triangles = 1;
  expect_error(error_after([](json&) {}, triangles), ErrorKind::TooLarge, "over 1 triangles");
  ModelLimits pixels;
  pixels.max_texture_pixels = 3;  // the 2 x 2 texture has 4
  expect_error(error_after([](json&) {}, pixels), ErrorKind::TooLarge,
               "image 0 is 2 x 2 pixels, over the limit of 3 pixels per texture");
  ModelLimits total;
  total.max_total_texture_pixels = 4;  // the normal map's 1 pixel goes over
  expect_error(error_after([](json&) {}, total), ErrorKind::TooLarge,
               "the model's textures are over 4 pixels together (at image 1)");
  ModelLimits bytes;
  bytes.max_file_bytes = 1000;
  try {
    load_model(test::model_path("gltf/quad.gltf"), bytes);
    ADD_FAILURE() << "loaded";
  } catch (const Error& e) {
    expect_error(e, ErrorKind::TooLarge, "bytes");
  }
}

TEST(GltfModel, AMirroringNodeReversesWindingAndHandedness) {
  json doc = quad_json();
  doc["nodes"][1]["scale"] = {-2, 2, 2};
  const std::string text = doc.dump();
  const Model m = load_gltf_memory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, "q", {});
  // Triangle 0 was (0, 1, 2); mirrored it is (0, 2, 1), so that it still faces its normal (glTF +z,
  // world -y).
  EXPECT_EQ(m.indices[1], 2u);
  const Vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]], c = m.positions[m.indices[2]];
  EXPECT_GT(dot(cross(b - a, c - a), m.normals[0]), 0.0f);
  EXPECT_EQ(m.normals[0], (Vec3{0, -1, 0}));
  EXPECT_NEAR(m.tangents[0].direction.x, -1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(m.tangents[0].w, -1.0f);
}

TEST(GltfModel, MissingNormalsGiveFlatShadingAndMissingUvsZero) {
  json doc = quad_json();
  doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
  doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
  const std::string text = doc.dump();
  const Model m = load_gltf_memory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, "q", {});
  EXPECT_EQ(m.vertex_count(), 6u);  // a vertex per corner
  for (const Vec3& n : m.normals) EXPECT_EQ(n, (Vec3{0, -1, 0}));
  for (const Point2& uv : m.uvs) EXPECT_EQ(uv.x + uv.y, 0.0f);
  for (const Tangent& t : m.tangents) EXPECT_NEAR(dot(t.direction, Vec3{0, -1, 0}), 0.0f, 1e-6f);
}

TEST(GltfModel, FilesOutsideTheModelFolderAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "lightprobe_model_escape";
  std::filesystem::create_directories(dir / "inner");
  json doc = json::parse(std::ifstream(test::model_path("gltf/quad.gltf")));
  std::filesystem::copy_file(test::model_path("gltf/quad.bin"), dir / "quad.bin",
                             std::filesystem::copy_options::overwrite_existing);
  for (const char* uri : {"../quad.bin", "/etc/passwd", "inner/../../quad.bin"}) {
    doc["buffers"][0]["uri"] = uri;
    std::ofstream(dir / "inner/escape.gltf") << doc.dump();
    try {
      load_model(dir / "inner/escape.gltf", {});
      ADD_FAILURE() << uri << " loaded";
    } catch (const Error& e) {
      EXPECT_TRUE(e.kind() == ErrorKind::InvalidArgument || e.kind() == ErrorKind::NotFound) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lp

// glTF material coverage and the optional vertex attributes on the test quad: alphaMode, alphaCutoff,
// doubleSided and KHR_materials_emissive_strength read; COLOR_0 in each of its forms; TEXCOORD_1 read
// when a texture uses it; nothing allocated for an attribute no primitive has.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using json = nlohmann::json;

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? bytes[i + k] : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

template <class T>
std::vector<uint8_t> bytes_of(const std::vector<T>& values) {
  std::vector<uint8_t> out(values.size() * sizeof(T));
  std::memcpy(out.data(), values.data(), out.size());
  return out;
}

json quad() {
  return json::parse(std::ifstream(test::model_path("quad_embedded.gltf")));
}

// Adds `data` as a buffer of its own with one accessor over it; returns the accessor's index.
int add_accessor(json& doc, const std::vector<uint8_t>& data, int component_type, const char* type,
                 size_t count, bool normalized = false) {
  doc["buffers"].push_back(
      {{"byteLength", data.size()}, {"uri", "data:application/octet-stream;base64," + base64(data)}});
  doc["bufferViews"].push_back({{"buffer", doc["buffers"].size() - 1}, {"byteLength", data.size()}});
  json accessor = {{"bufferView", doc["bufferViews"].size() - 1},
                   {"componentType", component_type},
                   {"count", count},
                   {"type", type}};
  if (normalized) accessor["normalized"] = true;
  doc["accessors"].push_back(accessor);
  return int(doc["accessors"].size() - 1);
}

Model load(const json& doc) {
  const std::string text = doc.dump();
  return load_gltf_memory({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, "quad.gltf", {});
}

ErrorKind load_error(const json& doc, std::string& message) {
  try {
    load(doc);
  } catch (const Error& e) {
    message = e.what();
    return e.kind();
  }
  ADD_FAILURE() << "loaded";
  return ErrorKind::Internal;
}

TEST(GltfCoverage, Base64OfTheTestHelperIsRight) {
  EXPECT_EQ(base64({'M', 'a', 'n'}), "TWFu");
  EXPECT_EQ(base64({'M', 'a'}), "TWE=");
  EXPECT_EQ(base64({'M'}), "TQ==");
}

TEST(GltfCoverage, AlphaModeCutoffSidesAndEmissiveStrength) {
  const Model plain = load(quad());
  EXPECT_EQ(plain.materials[0].alpha_mode, AlphaMode::Opaque);
  EXPECT_FLOAT_EQ(plain.materials[0].alpha_cutoff, 0.5f);
  EXPECT_FALSE(plain.materials[0].double_sided);  // glTF's default
  EXPECT_FLOAT_EQ(plain.materials[0].emissive_strength, 1.0f);
  json doc = quad();
  doc["materials"][0]["alphaMode"] = "MASK";
  doc["materials"][0]["alphaCutoff"] = 0.25;
  doc["materials"][0]["doubleSided"] = true;
  doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 5;
  doc["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  const Model m = load(doc);
  EXPECT_EQ(m.materials[0].alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.materials[0].alpha_cutoff, 0.25f);
  EXPECT_TRUE(m.materials[0].double_sided);
  EXPECT_FLOAT_EQ(m.materials[0].emissive_strength, 5.0f);
  doc["materials"][0]["alphaMode"] = "BLEND";
  EXPECT_EQ(load(doc).materials[0].alpha_mode, AlphaMode::Blend);
}

TEST(GltfCoverage, BadCoverageValuesAreRefused) {
  std::string message;
  json doc = quad();
  doc["materials"][0]["alphaMode"] = "CUTOUT";
  EXPECT_EQ(load_error(doc, message), ErrorKind::Corrupt);
  EXPECT_NE(message.find("alphaMode 'CUTOUT' is not OPAQUE, MASK or BLEND"), std::string::npos) << message;
  doc = quad();
  doc["materials"][0]["alphaCutoff"] = -1;
  EXPECT_EQ(load_error(doc, message), ErrorKind::Corrupt);
  EXPECT_NE(message.find("alphaCutoff -1 is not in"), std::string::npos) << message;
  doc = quad();
  doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -2;
  EXPECT_EQ(load_error(doc, message), ErrorKind::Corrupt);
  EXPECT_NE(message.find("emissiveStrength -2 is not in"), std::string::npos) << message;
  doc = quad();
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 2;
  EXPECT_EQ(load_error(doc, message), ErrorKind::Unsupported);
  EXPECT_NE(message.find("texture coordinates 2"), std::string::npos) << message;
}

TEST(GltfCoverage, VertexColoursInEveryForm) {
  struct Case {
    std::vector<uint8_t> data;
    int component_type;
    const char* type;
    Rgba expected;  // of vertex 1
  };
  const std::vector<Case> cases = {
      {bytes_of<float>({1, 1, 1, 0.5f, 0.25f, 0.75f, 1, 1, 1, 1, 1, 1}),
       5126,
       "VEC3",
       {0.5f, 0.25f, 0.75f, 1}},
      {bytes_of<float>({1, 1, 1, 1, 0.5f, 0.25f, 0.75f, 0.125f, 1, 1, 1, 1, 1, 1, 1, 1}),
       5126,
       "VEC4",
       {0.5f, 0.25f, 0.75f, 0.125f}},
      {bytes_of<uint8_t>({255, 255, 255, 255, 51, 102, 153, 204, 0, 0, 0, 0, 0, 0, 0, 0}),
       5121,
       "VEC4",
       {0.2f, 0.4f, 0.6f, 0.8f}},
      {bytes_of<uint16_t>({0, 0, 0, 65535, 0, 13107, 0, 0, 0, 0, 0, 0}), 5123, "VEC3", {1, 0, 0.2f, 1}},
  };
  for (const Case& c : cases) {
    json doc = quad();
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        add_accessor(doc, c.data, c.component_type, c.type, 4, c.component_type != 5126);
    const Model m = load(doc);
    ASSERT_EQ(m.colors.size(), m.vertex_count());
    EXPECT_FLOAT_EQ(m.colors[1].r, c.expected.r) << c.type << c.component_type;
    EXPECT_FLOAT_EQ(m.colors[1].g, c.expected.g);
    EXPECT_FLOAT_EQ(m.colors[1].b, c.expected.b);
    EXPECT_FLOAT_EQ(m.colors[1].a, c.expected.a);
    EXPECT_EQ(m.memory_bytes(), load(quad()).memory_bytes() + int64_t(4 * sizeof(Rgba)));
  }
  // Integers must be normalised.
  json doc = quad();
  doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
      add_accessor(doc, cases[2].data, 5121, "VEC4", 4, false);
  std::string message;
  EXPECT_EQ(load_error(doc, message), ErrorKind::Corrupt);
  EXPECT_NE(message.find("must be normalized"), std::string::npos) << message;
}

TEST(GltfCoverage, TheSecondTextureCoordinateSetIsReadWhenATextureUsesIt) {
  json doc = quad();
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] =
      add_accessor(doc, bytes_of<float>({0.5f, 0.25f, 1, 1, 0, 0, 0.75f, 0.5f}), 5126, "VEC2", 4);
  const Model unused = load(doc);
  EXPECT_TRUE(unused.uvs1.empty());
  EXPECT_TRUE(unused.colors.empty());
  EXPECT_EQ(unused.memory_bytes(), load(quad()).memory_bytes());  // nothing allocated for either
  doc["materials"][0]["normalTexture"]["texCoord"] = 1;
  const Model used = load(doc);
  ASSERT_EQ(used.uvs1.size(), used.vertex_count());
  EXPECT_FLOAT_EQ(used.uvs1[0].x, 0.5f);
  EXPECT_FLOAT_EQ(used.uvs1[3].y, 0.5f);
  EXPECT_EQ(used.materials[0].normal->tex_coord, 1);
  EXPECT_EQ(used.materials[0].base_color->tex_coord, 0);
  // KHR_texture_transform's texCoord overrides the texture's.
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]
     ["texCoord"] = 1;
  EXPECT_EQ(load(doc).materials[0].base_color->tex_coord, 1);
  // A primitive without the set the texture uses gets (0, 0), as one without TEXCOORD_0 does.
  doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_1");
  const Model missing = load(doc);
  ASSERT_EQ(missing.uvs1.size(), 0u);
}

}  // namespace
}  // namespace lp

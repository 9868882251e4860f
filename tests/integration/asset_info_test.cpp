// What an asset's record says of its model, on the real server: the bounds of the committed quad in the
// world frame (z up: glTF's (x, y, z) is (x, -z, y)), its counts, material features and textures, from a
// .glb and from a self-contained .gltf uploaded alone; what is ignored, as warnings saying where; and a
// model that does not load as a render would load it, refused at upload with 422 and nothing kept.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;

std::string file_text(const fs::path& path) {
  const auto bytes = test::read_bytes(path);
  return {bytes.begin(), bytes.end()};
}

json quad_gltf() {
  return json::parse(file_text(test::model_path("quad_embedded.gltf")));
}

Reply upload(test::ServerProcess& server, const std::string& name, const std::string& body) {
  return test::reply(
      server.client()->Post(("/api/v1/assets?name=" + name).c_str(), body, "application/octet-stream"));
}

Reply get(test::ServerProcess& server, const std::string& path) {
  return test::reply(server.client()->Get(path.c_str()));
}

bool listed(test::ServerProcess& server, const std::string& name) {
  const json list = get(server, "/api/v1/assets").body_json();
  for (const json& asset : list["assets"])
    if (asset["name"] == name) return true;
  return false;
}

// The quad: the unit square of glTF's z = 0 plane, scaled by 2 and moved by (1, 2, 3) through its node
// hierarchy, so x in [1, 3], y in [2, 4], z = 3 in glTF's frame; in the world (x, -z, y).
void expect_quad_description(const json& record) {
  SCOPED_TRACE(record.dump());
  constexpr double kTolerance = 1e-6;
  const json& bounds = record["bounds"];
  const double min[] = {1, -3, 2}, max[] = {3, -3, 4}, centre[] = {2, -3, 3};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(bounds["min"][i].get<double>(), min[i], kTolerance) << i;
    EXPECT_NEAR(bounds["max"][i].get<double>(), max[i], kTolerance) << i;
    EXPECT_NEAR(bounds["centre"][i].get<double>(), centre[i], kTolerance) << i;
  }
  EXPECT_NEAR(bounds["radius"].get<double>(), std::sqrt(2.0), kTolerance);  // the corners, from the centre
  EXPECT_EQ(record["triangles"], 2);
  EXPECT_EQ(record["vertices"], 4);
  EXPECT_EQ(record["meshes"], 1);
  EXPECT_EQ(record["materials"],
            json::parse(R"([{"name":"quad","features":["base_color_texture","normal_texture","emissive"],
                             "extensions":[]}])"));
  // A 2 x 2 RGB base colour (levels of 4 and 1 texels of 12 bytes) and a 1 x 1 normal map.
  EXPECT_EQ(record["textures"], json::parse(R"([{"width":2,"height":2,"bytes":60,"color_space":"srgb"},
                                                {"width":1,"height":1,"bytes":12,"color_space":"linear"}])"));
  EXPECT_EQ(record["cameras"], json::array());
  EXPECT_EQ(record["extensions_used"], json::array({"KHR_texture_transform"}));
  EXPECT_EQ(record["warnings"], json::array());
}

TEST(AssetInfo, AGlbsRecordDescribesItsModelInTheWorldFrame) {
  auto& s = test::shared_server();
  const Reply r = upload(s, "info_quad_glb", file_text(test::model_path("quad.glb")));
  ASSERT_EQ(r.status, 201) << r.body;
  expect_quad_description(r.body_json());
  EXPECT_EQ(get(s, "/api/v1/assets/info_quad_glb").body_json(), r.body_json());
  ASSERT_TRUE(listed(s, "info_quad_glb"));
}

TEST(AssetInfo, ASelfContainedGltfIsAcceptedAloneAndRenders) {
  auto& s = test::shared_server();
  const Reply r = upload(s, "info_quad_gltf", file_text(test::model_path("quad_embedded.gltf")));
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(r.body_json()["model"], "model.gltf");
  EXPECT_EQ(r.body_json()["format"], "gltf");
  EXPECT_EQ(r.body_json()["files"], 1);
  expect_quad_description(r.body_json());
  const json body = {{"envmap", "studio_hdr"},
                     {"width", 8},
                     {"height", 8},
                     {"spp", 1},
                     {"scene", {{"objects", {{{"type", "mesh"}, {"path", "assets/info_quad_gltf"}}}}}}};
  const Reply render = test::reply(s.client()->Post("/api/v1/renders", body.dump(), "application/json"));
  ASSERT_EQ(render.status, 202) << render.body;
  EXPECT_EQ(test::finished_render(*s.client(), render.body_json()["id"])["status"], "done");
}

TEST(AssetInfo, WhatIsIgnoredIsAWarningSayingWhere) {
  json doc = quad_gltf();
  doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_anisotropy", "KHR_materials_variants",
                           "EXT_unknown_everywhere"};
  doc["materials"][0]["extensions"]["KHR_materials_anisotropy"] = {{"anisotropyStrength", 0.5}};
  doc["extensions"]["KHR_materials_variants"] = {{"variants", {{{"name", "red"}}}}};
  doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "scale"}}}}}},
                        {"samplers", {{{"input", 2}, {"output", 0}}}}}};
  doc["skins"] = {{{"joints", {1}}}};
  doc["cameras"] = {
      {{"type", "perspective"}, {"name", "front"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}},
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
  auto& s = test::shared_server();
  const Reply r = upload(s, "info_warned", doc.dump());
  ASSERT_EQ(r.status, 201) << r.body;
  const json record = r.body_json();
  EXPECT_EQ(record["warnings"],
            json::array({"the document: KHR_materials_variants is not supported and is ignored: every "
                         "primitive keeps its default material",
                         "materials[0]: KHR_materials_anisotropy is not supported and is ignored",
                         "extensionsUsed: EXT_unknown_everywhere is not supported and is ignored",
                         "animations: 1 animation(s) are ignored: the model is rendered at rest",
                         "skins: 1 skin(s) are ignored: skinned meshes are rendered at rest"}));
  EXPECT_EQ(record["materials"][0]["extensions"], json::array({"KHR_materials_anisotropy"}));
  EXPECT_EQ(record["extensions_used"], doc["extensionsUsed"]);
  EXPECT_EQ(record["cameras"], json::parse(R"([{"index":0,"name":"front","type":"perspective"},
                                                {"index":1,"name":"","type":"orthographic"}])"));
  EXPECT_EQ(record["triangles"], 2);
}

struct BrokenModel {
  std::string label, name, body, message;
};

std::vector<BrokenModel> broken_models() {
  const std::string glb = file_text(test::model_path("quad.glb"));
  json bad_accessor = quad_gltf();
  bad_accessor["accessors"][0]["count"] = 5;
  json required = quad_gltf();
  required["extensionsUsed"].push_back("KHR_draco_mesh_compression");
  required["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  return {
      {"truncated .glb", "info_truncated", glb.substr(0, glb.size() - 40), "glb model.glb"},
      {"accessor past its buffer view", "info_accessor", bad_accessor.dump(),
       "mesh 0 primitive 0 POSITION (accessor 0): 5 elements from byte offset 0 lie outside its buffer view"},
      {"a required extension not read", "info_required", required.dump(),
       "requires the extension KHR_draco_mesh_compression, which is not supported"},
  };
}

TEST(AssetInfo, AModelThatDoesNotLoadIsRefusedAt422AndNothingIsKept) {
  auto& s = test::shared_server();
  for (const BrokenModel& broken : broken_models()) {
    SCOPED_TRACE(broken.label);
    const Reply r = upload(s, broken.name, broken.body);
    EXPECT_EQ(r.status, 422) << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "invalid_model") << r.body;
    EXPECT_NE(r.body_json()["error"]["message"].get<std::string>().find(broken.message), std::string::npos)
        << r.body;
    EXPECT_FALSE(listed(s, broken.name));
    EXPECT_EQ(get(s, "/api/v1/assets/" + broken.name).status, 404);
  }
}

TEST(AssetInfo, TheRecordIsKeptAcrossARestartAndNoFileOfARefusedUploadIs) {
  test::TempDir state;
  const std::vector<std::string> flags = {"--state-dir", state.path().string()};
  json before;
  {
    test::ServerProcess s(flags);
    const Reply r = upload(s, "quad", file_text(test::model_path("quad.glb")));
    ASSERT_EQ(r.status, 201) << r.body;
    before = r.body_json();
    for (const BrokenModel& broken : broken_models())
      EXPECT_EQ(upload(s, broken.name, broken.body).status, 422);
  }
  std::set<std::string> kept;
  for (const auto& folder : {"assets", "asset-files"})
    for (const auto& entry : fs::directory_iterator(state.path() / folder))
      kept.insert(std::string(folder) + "/" + entry.path().filename().string());
  EXPECT_EQ(kept, (std::set<std::string>{"asset-files/quad", "assets/quad.json"}));
  test::ServerProcess s(flags);
  EXPECT_EQ(get(s, "/api/v1/assets/quad").body_json(), before);
}

}  // namespace
}  // namespace lp

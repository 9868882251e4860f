// Scenes with glTF and OBJ models on the real server: an uploaded .glb (Khronos BoxTextured from
// assimp-testmodels) and a .gltf with external buffer and texture in the data directory render to done;
// every malformed glTF sample of assimp-testmodels is a 400 naming the mesh path at submit, and the
// server keeps serving; a model file replaced on disk is loaded again (the model cache follows the file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;

const fs::path kGltfSamples = "/usr/share/assimp/models/glTF2";

// A data directory holding copies of assimp's glTF samples (the well-formed BoxTextured and the
// malformed ones), and a server on it with its own state directory for uploads.
class ModelServer {
 public:
  ModelServer() {
    for (const char* folder : {"BoxTextured-glTF", "wrongTypes", "IndexOutOfRange", "RecursiveNodes",
                               "MissingBin", "BoxWithInfinites-glTF-Binary"})
      fs::copy(kGltfSamples / folder, data_.path() / folder, fs::copy_options::recursive);
    server_ = std::make_unique<test::ServerProcess>(
        std::vector<std::string>{"--data-dir", data_.path().string(), "--state-dir", state_.path().string()});
    client_ = server_->client();
  }
  const fs::path& data_dir() const { return data_.path(); }
  Reply get(const std::string& path) const { return test::reply(client_->Get(path.c_str())); }
  Reply upload(const std::string& name, const std::string& body) const {
    return test::reply(
        client_->Post(("/api/v1/assets?name=" + name).c_str(), body, "application/octet-stream"));
  }
  Reply render(const std::string& mesh_path) const {
    const json mesh = {{"type", "mesh"}, {"path", mesh_path}};
    const json body = {
        {"envmap", "default"}, {"width", 16}, {"height", 16}, {"spp", 2}, {"scene", {{"objects", {mesh}}}}};
    return test::reply(client_->Post("/api/v1/renders", body.dump(), "application/json"));
  }
  // Submits and waits for the render to leave the queue; returns its final status.
  json render_to_end(const std::string& mesh_path) const {
    const Reply r = render(mesh_path);
    EXPECT_EQ(r.status, 202) << mesh_path << ": " << r.body;
    if (r.status != 202) return {};
    return test::finished_render(*client_, r.body_json()["id"]);
  }
  httplib::Client* client() const { return client_.get(); }
  Reply post(const json& body) const {
    return test::reply(client_->Post("/api/v1/renders", body.dump(), "application/json"));
  }
  bool alive() const { return server_->alive(); }

 private:
  test::TempDir data_, state_;
  std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<httplib::Client> client_;
};

ModelServer& model_server() {
  static ModelServer server;
  return server;
}

void expect_refused_path(const Reply& r, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(r.status, 400) << r.body;
  if (r.status != 400) return;
  const json error = r.body_json()["error"];
  EXPECT_EQ(error["code"], "invalid_field");
  EXPECT_NE(error["message"].get<std::string>().find("scene.objects[0].path"), std::string::npos) << r.body;
}

TEST(ModelRender, AnUploadedGlbRendersToDone) {
  auto& s = model_server();
  const auto glb = test::read_bytes(kGltfSamples / "BoxTextured-glTF-Binary" / "BoxTextured.glb");
  const Reply up = s.upload("box", std::string(glb.begin(), glb.end()));
  ASSERT_EQ(up.status, 201) << up.body;
  EXPECT_EQ(s.render_to_end("assets/box")["status"], "done");
  // The second render of the same file uses the cached model.
  EXPECT_EQ(s.render_to_end("assets/box")["status"], "done");
}

TEST(ModelRender, AGltfWithExternalBufferAndTextureRendersToDone) {
  EXPECT_EQ(model_server().render_to_end("BoxTextured-glTF/BoxTextured.gltf")["status"], "done");
}

TEST(ModelRender, MalformedGltfIsRefusedAtSubmitAndTheServerKeepsServing) {
  auto& s = model_server();
  for (const char* bad :
       {"wrongTypes/badArray.gltf", "wrongTypes/badExtension.gltf", "wrongTypes/badNumber.gltf",
        "wrongTypes/badObject.gltf", "wrongTypes/badString.gltf", "wrongTypes/badUint.gltf",
        "IndexOutOfRange/IndexOutOfRange.gltf", "IndexOutOfRange/AllIndicesOutOfRange.gltf",
        "RecursiveNodes/RecursiveNodes.gltf", "MissingBin/BoxTextured.gltf",
        "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"})
    expect_refused_path(s.render(bad), bad);
  const auto garbage = std::string("glTF\x02\0\0\0", 8) + "not a binary glTF";
  ASSERT_EQ(s.upload("garbage", garbage).status, 201);
  expect_refused_path(s.render("assets/garbage"), "a .glb of garbage");
  EXPECT_TRUE(s.alive());
  EXPECT_EQ(s.get("/api/v1/health").status, 200);
  EXPECT_EQ(s.render_to_end("BoxTextured-glTF/BoxTextured.gltf")["status"], "done");
}

TEST(ModelRender, AModelFileReplacedOnDiskIsLoadedAgain) {
  auto& s = model_server();
  const fs::path file = s.data_dir() / "grid.obj";
  std::ofstream(file) << test::grid_obj(3);
  EXPECT_EQ(s.render_to_end("grid.obj")["status"], "done");
  std::ofstream(file) << "v 0 0 0\nf 1 2 3\n";  // a face naming missing vertices
  expect_refused_path(s.render("grid.obj"), "the replaced file");
  std::ofstream(file) << test::grid_obj(2);
  EXPECT_EQ(s.render_to_end("grid.obj")["status"], "done");
}

TEST(ModelRender, TheTexturedPresetRendersToDoneWithMipmapsAndNormalMapsOnAndOff) {
  auto& s = model_server();
  for (const auto& [mipmaps, normal_maps] : {std::pair{true, true}, {false, true}, {true, false}}) {
    const json body = {{"envmap", "default"},
                       {"width", 24},
                       {"height", 16},
                       {"spp", 2},
                       {"mipmaps", mipmaps},
                       {"normal_maps", normal_maps},
                       {"scene", {{"preset", "textured"}}}};
    const Reply r = s.post(body);
    ASSERT_EQ(r.status, 202) << r.body;
    const json st = test::finished_render(*s.client(), r.body_json()["id"]);
    EXPECT_EQ(st["status"], "done") << st.dump();
    EXPECT_EQ(st["scene"]["preset"], "textured");
    EXPECT_EQ(st["mipmaps"], mipmaps);
    EXPECT_EQ(st["normal_maps"], normal_maps);
    const Reply image = s.get("/api/v1/renders/" + r.body_json()["id"].get<std::string>() + "/image");
    EXPECT_EQ(image.status, 200);
  }
}

TEST(ModelRender, OtherFileTypesAreRefusedNamingTheExtensions) {
  auto& s = model_server();
  std::ofstream(s.data_dir() / "grid.ply") << "ply\n";
  const Reply r = s.render("grid.ply");
  expect_refused_path(r, "a .ply");
  EXPECT_NE(r.body.find(".gltf, .glb or .obj"), std::string::npos) << r.body;
}

}  // namespace
}  // namespace lp

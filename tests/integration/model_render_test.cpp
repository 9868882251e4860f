// Scenes with glTF and OBJ models on the real server: an uploaded .glb (Khronos BoxTextured from
// assimp-testmodels) and a .gltf with external buffer and texture in the data directory render to done;
// every glTF sample of assimp-testmodels the loader refuses (support/gltf_samples.hpp: malformed,
// glTF 1.0, unsupported) is a 400 naming the mesh path at submit, every other one renders to done, and
// the server keeps serving (a .glb of garbage is refused at upload); a model file replaced on disk, or a
// texture of it edited, is loaded again (the model cache follows every file a model was read from); textures
// over --max-texture-pixels or
// --max-model-texture-pixels are a 400 naming the limit at submit.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/image/image_io.hpp"
#include "support/gltf_samples.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;

// A 16 x 16 render of a scene holding the one model at `mesh_path`, under the default map.
json mesh_scene(const std::string& mesh_path) {
  const json mesh = {{"type", "mesh"}, {"path", mesh_path}};
  return {{"envmap", "default"}, {"width", 16}, {"height", 16}, {"spp", 2}, {"scene", {{"objects", {mesh}}}}};
}

// A data directory holding copies of assimp's glTF samples (its folders glTF2 and glTF, 4 MB), and a
// server on it with its own state directory for uploads.
class ModelServer {
 public:
  ModelServer() {
    for (const char* folder : {"glTF2", "glTF"})
      fs::copy(test::assimp_model_path(folder), data_.path() / folder, fs::copy_options::recursive);
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
  Reply render(const std::string& mesh_path) const { return post(mesh_scene(mesh_path)); }
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
  const auto glb = test::read_bytes(test::assimp_model_path("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  const Reply up = s.upload("box", std::string(glb.begin(), glb.end()));
  ASSERT_EQ(up.status, 201) << up.body;
  EXPECT_EQ(s.render_to_end("assets/box")["status"], "done");
  // The second render of the same file uses the cached model.
  EXPECT_EQ(s.render_to_end("assets/box")["status"], "done");
}

TEST(ModelRender, AGltfWithExternalBufferAndTextureRendersToDone) {
  EXPECT_EQ(model_server().render_to_end("glTF2/BoxTextured-glTF/BoxTextured.gltf")["status"], "done");
}

TEST(ModelRender, EveryGltfSampleIsRefusedAtSubmitOrRendersAndTheServerKeepsServing) {
  auto& s = model_server();
  for (const auto& [bad, kind] : test::refused_gltf_samples()) expect_refused_path(s.render(bad), bad);
  for (const auto& [good, triangles] : test::valid_gltf_samples())
    EXPECT_EQ(s.render_to_end(good)["status"], "done") << good;
  const auto garbage = std::string("glTF\x02\0\0\0", 8) + "not a binary glTF";
  const Reply refused = s.upload("garbage", garbage);
  EXPECT_EQ(refused.status, 422) << refused.body;
  EXPECT_EQ(refused.body_json()["error"]["code"], "invalid_model") << refused.body;
  EXPECT_TRUE(s.alive());
  EXPECT_EQ(s.get("/api/v1/health").status, 200);
  EXPECT_EQ(s.render_to_end("glTF2/BoxTextured-glTF/BoxTextured.gltf")["status"], "done");
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

// The mean colour of an 8 x 8 render of the quad of test::write_textured_quad at `mesh_path` (an OBJ
// written z-up, in z = 0), seen face-on so that it fills the view, under a constant white map.
Rgb quad_colour(const ModelServer& s, const std::string& mesh_path) {
  test::ensure_white_map(*s.client(), "white");
  json body = mesh_scene(mesh_path);
  body["envmap"] = "white";
  body["scene"]["objects"][0]["up_axis"] = "z";
  body["width"] = body["height"] = 8;
  body["spp"] = 16;
  body["scene"]["camera"] = {
      {"position", {0.5, 0.5, 2}}, {"look_at", {0.5, 0.5, 0}}, {"up", {0, 1, 0}}, {"fov_deg", 20}};
  const Reply r = s.post(body);
  EXPECT_EQ(r.status, 202) << r.body;
  if (r.status != 202) return {};
  const std::string id = r.body_json()["id"];
  EXPECT_EQ(test::finished_render(*s.client(), id)["status"], "done");
  const Reply pixels = s.get("/api/v1/renders/" + id + "/image?format=pfm");
  const Image img =
      read_image({reinterpret_cast<const uint8_t*>(pixels.body.data()), pixels.body.size()}).image;
  Rgb sum{0, 0, 0};
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) sum = sum + img.at(x, y);
  return sum / float(img.width() * img.height());
}

// A texture edited in place (same path, model file untouched) shows in the next render: the cache
// compares the modification time and size of every file the model read, the textures included. Under a
// white map a white material with a red albedo texture reflects almost all of the red, and in the other
// channels only the dielectric's specular reflection (1.3% at roughness 1).
TEST(ModelRender, AnEditedTextureIsPickedUpByTheNextRender) {
  auto& s = model_server();
  const fs::path folder = s.data_dir() / "edited_texture";
  fs::create_directory(folder);
  test::write_textured_quad(folder, test::solid_png(2, 2, {255, 0, 0}));
  const Rgb red = quad_colour(s, "edited_texture/quad.obj");
  EXPECT_GT(red.x, 0.9f);
  EXPECT_LT(red.y, 0.05f);
  EXPECT_LT(red.z, 0.05f);
  const auto before = fs::last_write_time(folder / "albedo.png");
  std::ofstream(folder / "albedo.png", std::ios::binary) << test::solid_png(2, 2, {0, 255, 0});
  fs::last_write_time(folder / "albedo.png", before + std::chrono::seconds(1));  // coarse file-system clocks
  const Rgb green = quad_colour(s, "edited_texture/quad.obj");
  EXPECT_LT(green.x, 0.05f);
  EXPECT_GT(green.y, 0.9f);
  EXPECT_LT(green.z, 0.05f);
  EXPECT_NEAR(green.y, red.x, 0.02f);  // the same quad with the channels swapped
}

// A mesh object's `up_axis` names an OBJ file's up axis; a glTF is y-up by its specification, so z on
// one is a 400 naming the field, as is a name that is not an axis.
TEST(ModelRender, UpAxisZIsForObjFilesAndNamesAnAxis) {
  auto& s = model_server();
  const fs::path file = s.data_dir() / "up_grid.obj";
  std::ofstream(file) << test::grid_obj(2);
  for (const char* axis : {"y", "z"}) {
    json body = mesh_scene("up_grid.obj");
    body["scene"]["objects"][0]["up_axis"] = axis;
    EXPECT_EQ(s.post(body).status, 202) << axis;
  }
  const auto refused = [&](const std::string& path, const std::string& axis) {
    json body = mesh_scene(path);
    body["scene"]["objects"][0]["up_axis"] = axis;
    const Reply r = s.post(body);
    EXPECT_EQ(r.status, 400) << r.body;
    const json error = r.body_json()["error"];
    EXPECT_EQ(error["code"], "invalid_field");
    return error["message"].get<std::string>();
  };
  EXPECT_EQ(
      refused("glTF2/BoxTextured-glTF/BoxTextured.gltf", "z"),
      "field 'scene.objects[0].up_axis': a glTF model is y-up by its specification; z applies to OBJ files");
  EXPECT_NE(refused("up_grid.obj", "x").find("'scene.objects[0].up_axis'"), std::string::npos);
  json gltf_y = mesh_scene("glTF2/BoxTextured-glTF/BoxTextured.gltf");
  gltf_y["scene"]["objects"][0]["up_axis"] = "y";
  EXPECT_EQ(s.post(gltf_y).status, 202);
}

// Each texture's pixels and all of a model's together are limited by flags: a model over either is a
// 400 at submit naming the field, the texture and the limit; the server keeps serving models under them.
TEST(ModelRender, TexturesOverThePixelLimitsAreRefusedAtSubmit) {
  const test::TempDir data;
  for (const char* folder : {"small", "large", "two"}) fs::create_directory(data.path() / folder);
  test::write_textured_quad(data.path() / "small", test::solid_png(4, 4, {200, 200, 200}));
  test::write_textured_quad(data.path() / "large", test::solid_png(5, 4, {200, 200, 200}));
  test::write_textured_quad(data.path() / "two", test::solid_png(4, 4, {200, 200, 200}),
                            test::solid_png(4, 4, {128, 128, 255}));
  test::ServerProcess server(
      {"--data-dir", data.path().string(), "--max-texture-pixels", "16", "--max-model-texture-pixels", "24"});
  auto client = server.client();
  const auto submit = [&](const std::string& path) {
    return test::reply(client->Post("/api/v1/renders", mesh_scene(path).dump(), "application/json"));
  };
  const Reply large = submit("large/quad.obj");
  expect_refused_path(large, "a 5 x 4 texture");
  EXPECT_NE(large.body.find("albedo.png is 5 x 4 pixels, over the limit of 16 pixels per texture"),
            std::string::npos)
      << large.body;
  const Reply two = submit("two/quad.obj");
  expect_refused_path(two, "two 4 x 4 textures");
  EXPECT_NE(two.body.find("the model's textures are over 24 pixels together"), std::string::npos) << two.body;
  const Reply small = submit("small/quad.obj");
  ASSERT_EQ(small.status, 202) << small.body;
  EXPECT_EQ(test::finished_render(*client, small.body_json()["id"])["status"], "done");
  EXPECT_TRUE(server.alive());
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

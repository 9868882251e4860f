// What the camera sees of a user's model on the real server: a glTF enters the world as Blender shows it
// (a labelled quad reads right way round from the default framed camera), a scene without a camera
// frames its objects (a real engine model hundreds of units across is framed and lit, not black), a
// camera of the glTF file renders, and a view that sees nothing or sits inside a model says so in the
// render's status.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;

// A 2 x 2 unit quad in glTF's z = 0 plane facing its front (+z), emitting a 2 x 2 texture (nearest
// filtered) on a black metal, so a pixel on it is its texel: red top-left, green top-right, blue
// bottom-left, white bottom-right as the image is stored, upright when the quad is seen from the front
// with glTF's +y up. A perspective camera "front" (yfov 0.6) stands 5 in front of it, 1 above.
// `material` is merged into the quad's material, and the file is written as `name`.
void write_labelled_quad(const fs::path& folder, const std::string& name = "label.gltf",
                         const json& material = json::object()) {
  const float positions[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::ofstream bin(folder / "label.bin", std::ios::binary);
  bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
  bin.write(reinterpret_cast<const char*>(normals), sizeof normals);
  bin.write(reinterpret_cast<const char*>(uvs), sizeof uvs);
  bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
  bin.close();
  const uint8_t texels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  const std::vector<uint8_t> png = encode_png_rgb8(texels, 2, 2);
  std::ofstream(folder / "label.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  const json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", {{{"mesh", 0}}, {{"camera", 0}, {"translation", {0, 1, 5}}}}},
      {"cameras",
       {{{"type", "perspective"}, {"name", "front"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.1}}}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
            {"indices", 3},
            {"material", 0}}}}}}},
      {"materials",
       {{{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 1}}},
         {"emissiveFactor", {1, 1, 1}},
         {"emissiveTexture", {{"index", 0}}}}}},
      {"textures", {{{"source", 0}, {"sampler", 0}}}},
      {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},
      {"images", {{{"uri", "label.png"}}}},
      {"buffers", {{{"uri", "label.bin"}, {"byteLength", 140}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
        {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-1, -1, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}}};
  json file = gltf;
  file["materials"][0].update(material);
  if (material.contains("extensions"))
    for (const auto& [extension, value] : material["extensions"].items())
      file["extensionsUsed"].push_back(extension);
  std::ofstream(folder / name) << file.dump();
}

class ViewServer {
 public:
  ViewServer() {
    write_labelled_quad(data_.path());
    write_labelled_quad(
        data_.path(), "masked.gltf",
        {{"alphaMode", "MASK"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 0.4}}, {"metallicFactor", 1}}}});
    write_labelled_quad(data_.path(), "bright.gltf",
                        {{"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5}}}}}});
    fs::copy(test::assimp_model_path("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"),
             data_.path() / "engine.glb");
    server_ =
        std::make_unique<test::ServerProcess>(std::vector<std::string>{"--data-dir", data_.path().string()});
    client_ = server_->client();
  }
  Reply post(const json& body) const {
    return test::reply(client_->Post("/api/v1/renders", body.dump(), "application/json"));
  }
  // The final status of an accepted render.
  json render(const json& body) const {
    const Reply r = post(body);
    EXPECT_EQ(r.status, 202) << r.body;
    if (r.status != 202) return {};
    return test::finished_render(*client_, r.body_json()["id"]);
  }
  Image image(const json& status) const {
    const std::string url = "/api/v1/renders/" + status["id"].get<std::string>() + "/image?format=pfm";
    const Reply pixels = test::reply(client_->Get(url.c_str()));
    return read_image({reinterpret_cast<const uint8_t*>(pixels.body.data()), pixels.body.size()}).image;
  }

 private:
  test::TempDir data_;
  std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<httplib::Client> client_;
};

ViewServer& view_server() {
  static ViewServer server;
  return server;
}

json body_of(const std::vector<json>& objects, const json& camera = nullptr) {
  json body = {
      {"envmap", "default"}, {"width", 64}, {"height", 64}, {"spp", 4}, {"lighting", {{"visible", false}}}};
  body["scene"] = {{"objects", objects}};
  if (!camera.is_null()) body["scene"]["camera"] = camera;
  return body;
}

Vec3 vec(const json& v) {
  return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
}

// The pixel of `image` the world point p falls in, through the camera the status reports.
Rgb pixel_at(const Image& image, const json& camera, Vec3 p) {
  const Vec3 eye = vec(camera["position"]), forward = normalize(vec(camera["look_at"]) - eye);
  const Vec3 right = normalize(cross(forward, vec(camera["up"]))), up = cross(right, forward);
  const float half = std::tan(0.5f * camera["fov_deg"].get<float>() * 3.14159265f / 180);
  const Vec3 d = p - eye;
  const float sx = dot(d, right) / dot(d, forward) / half, sy = dot(d, up) / dot(d, forward) / half;
  return image.at(int((sx + 1) / 2 * float(image.width())), int((1 - sy) / 2 * float(image.height())));
}

// A pixel at a quadrant's centre is its texel, up to what the mip filter of the pixel's footprint mixes in
// from the 2 x 2 texture's coarser level (measured under 0.035).
void expect_rgb(Rgb got, Rgb expected, const std::string& what) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], expected[k], 0.05f) << what << " channel " << k;
}

// glTF (x, y, z) enters as (x, -z, y): the quad stands in y = 0 facing -y, and from the default camera
// (in front, slightly above) its top-left texel is at the top left, its image not mirrored or upside down.
TEST(ModelView, ALabelledGltfReadsRightWayRoundFromTheDefaultFramedCamera) {
  const auto& s = view_server();
  const json st = s.render(body_of({{{"type", "mesh"}, {"path", "label.gltf"}}}));
  ASSERT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["warnings"], json::array());
  const json& camera = st["camera"];
  EXPECT_LT(camera["position"][1].get<float>(), -1.0f);  // in front (-y)
  EXPECT_GT(camera["position"][2].get<float>(), 0.1f);   // slightly above
  const Image image = s.image(st);
  expect_rgb(pixel_at(image, camera, {-0.5f, 0, 0.5f}), {1, 0, 0}, "top left");
  expect_rgb(pixel_at(image, camera, {0.5f, 0, 0.5f}), {0, 1, 0}, "top right");
  expect_rgb(pixel_at(image, camera, {-0.5f, 0, -0.5f}), {0, 0, 1}, "bottom left");
  expect_rgb(pixel_at(image, camera, {0.5f, 0, -0.5f}), {1, 1, 1}, "bottom right");
}

// 2CylinderEngine is hundreds of units across; the old fixed camera at (0, -4, 0) sat inside it and
// rendered black. Framed, it covers a good part of the image, lit by the map (the map itself hidden).
TEST(ModelView, ARealModelHundredsOfUnitsAcrossIsFramedAndLit) {
  const auto& s = view_server();
  const json st = s.render(body_of({{{"type", "mesh"}, {"path", "engine.glb"}}}));
  ASSERT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["warnings"], json::array());
  EXPECT_GT(length(vec(st["camera"]["position"])), 100.0f);
  const Image image = s.image(st);
  int lit = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) lit += max_component(image.at(x, y)) > 0.01f;
  EXPECT_GT(lit, image.width() * image.height() / 5) << "pixels showing the model";
}

TEST(ModelView, AGltfCameraRendersFromWhereTheFilePutsIt) {
  const auto& s = view_server();
  const json mesh = {{"type", "mesh"}, {"path", "label.gltf"}};
  for (const json& which : {json("front"), json(0), json{{"camera", "front"}, {"object", 0}}}) {
    const json st = s.render(body_of({mesh}, {{"gltf", which}}));
    ASSERT_EQ(st["status"], "done") << st.dump();
    // glTF (0, 1, 5) looking down -z with +y up: world (0, -5, 1) looking along +y with +z up.
    const json& camera = st["camera"];
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(camera["position"][k].get<float>(), (std::vector<float>{0, -5, 1})[size_t(k)], 1e-5f);
      EXPECT_NEAR(camera["look_at"][k].get<float>(), (std::vector<float>{0, -4, 1})[size_t(k)], 1e-5f);
      EXPECT_NEAR(camera["up"][k].get<float>(), (std::vector<float>{0, 0, 1})[size_t(k)], 1e-5f);
    }
    EXPECT_NEAR(camera["fov_deg"].get<float>(), 0.6f * 180 / 3.14159265f, 1e-4f);
    const Image image = s.image(st);
    expect_rgb(pixel_at(image, camera, {-0.5f, 0, 0.5f}), {1, 0, 0}, "top left");
    expect_rgb(pixel_at(image, camera, {0.5f, 0, -0.5f}), {1, 1, 1}, "bottom right");
  }
}

// Material features on the real server, against their analytic answers: a quad masked out (alpha 0.4
// under the default cutoff 0.5) lets exactly the map through, pixel for pixel the image without it; an
// emissive strength of 5 gives 5 times the emission.
TEST(ModelView, AMaskedOutQuadShowsExactlyTheMapAndEmissiveStrengthScales) {
  const auto& s = view_server();
  const json camera = {{"position", {0, -5, 0}}, {"look_at", {0, 0, 0}}, {"fov_deg", 30}};
  json visible = body_of({{{"type", "mesh"}, {"path", "masked.gltf"}}}, camera);
  visible["lighting"]["visible"] = true;
  json empty = visible;
  empty["scene"]["objects"] = json::array();
  const json masked = s.render(visible), bare = s.render(empty);
  ASSERT_EQ(masked["status"], "done") << masked.dump();
  const Image a = s.image(masked), b = s.image(bare);
  float largest = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(a.at(x, y)[k] - b.at(x, y)[k]));
  EXPECT_EQ(largest, 0.0f);

  // Unlit (map intensity 0), so a pixel is the emission alone.
  const auto unlit = [&](const std::string& path) {
    json body = body_of({{{"type", "mesh"}, {"path", path}}}, camera);
    body["lighting"]["intensity"] = 0;
    return s.render(body);
  };
  const json plain = unlit("label.gltf"), bright = unlit("bright.gltf");
  const Image one = s.image(plain), five = s.image(bright);
  for (const Vec3 p :
       {Vec3{-0.5f, 0, 0.5f}, Vec3{0.5f, 0, 0.5f}, Vec3{-0.5f, 0, -0.5f}, Vec3{0.5f, 0, -0.5f}}) {
    const Rgb e1 = pixel_at(one, plain["camera"], p), e5 = pixel_at(five, bright["camera"], p);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e5[k], 5 * e1[k], 1e-5f + 1e-5f * e5[k]) << k;
  }
}

TEST(ModelView, AViewThatSeesNothingOrSitsInsideAModelSaysSo) {
  const auto& s = view_server();
  const json engine = {{"type", "mesh"}, {"path", "engine.glb"}};
  const json inside = s.render(body_of({engine}, {{"position", {0, -4, 0}}, {"look_at", {0, 0, 0}}}));
  ASSERT_EQ(inside["status"], "done") << inside.dump();
  ASSERT_EQ(inside["warnings"].size(), 1u) << inside.dump();
  EXPECT_NE(inside["warnings"][0].get<std::string>().find("inside the bounds of scene.objects[0]"),
            std::string::npos);
  const json sphere = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}};
  const json away = s.render(body_of({sphere}, {{"position", {0, -4, 0}}, {"look_at", {0, -8, 0}}}));
  ASSERT_EQ(away["status"], "done") << away.dump();
  EXPECT_EQ(
      away["warnings"],
      json::array({"the camera's view holds none of the scene's objects: the image shows only the map"}));
  const json seen = s.render(body_of({sphere}, {{"position", {0, -4, 0}}, {"look_at", {0, 0, 0}}}));
  EXPECT_EQ(seen["warnings"], json::array());
}

TEST(ModelView, ACameraThatCannotBeResolvedIsA400NamingIt) {
  const auto& s = view_server();
  const json mesh = {{"type", "mesh"}, {"path", "label.gltf"}};
  const json plane = {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}};
  const auto refused = [&](const json& body, const std::string& field) {
    const Reply r = s.post(body);
    EXPECT_EQ(r.status, 400) << r.body;
    const std::string message = r.body_json()["error"]["message"];
    EXPECT_NE(message.find("'" + field + "'"), std::string::npos) << message;
    return message;
  };
  refused(body_of({mesh}, {{"fit", {{"object", 3}}}}), "scene.camera.fit.object");
  refused(body_of({mesh, plane}, {{"fit", {{"object", 1}}}}), "scene.camera.fit.object");
  refused(body_of({plane}, {{"fit", json::object()}}), "scene.camera.fit");
  refused(body_of({mesh}, {{"fit", {{"elevation_deg", 90}}}}), "scene.camera.fit.elevation_deg");
  refused(body_of({mesh}, {{"fit", json::object()}, {"position", {0, 0, 1}}}), "scene.camera.position");
  EXPECT_NE(refused(body_of({mesh}, {{"gltf", "back"}}), "scene.camera.gltf").find("0 'front'"),
            std::string::npos);
  refused(body_of({mesh}, {{"gltf", 2}}), "scene.camera.gltf");
  refused(body_of({mesh}, {{"gltf", -1}}), "scene.camera.gltf");
  // A plane alone and no camera: nothing to frame, so the fixed default camera, and no error.
  EXPECT_EQ(s.post(body_of({plane})).status, 202);
}

}  // namespace
}  // namespace lp

// Backgrounds, passes and the ground through the real server: a transparent render's corner has alpha 0
// and its sphere alpha 1 in the alpha pass, the RGBA PNG (straight alpha) and the RGBA EXR
// (premultiplied), the RGBA WebP and its thumbnail, the JPEG over white; the albedo, normal and depth passes
// of a white sphere; pass=all as one EXR whose channels OpenEXR reads by name; a shadow catcher's alpha; and
// the refusals (a pass not asked for, pass=all outside EXR, bad fields).
#include <gtest/gtest.h>
#include <stb_image.h>
#include <webp/decode.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "support/exr_channels.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/white_map.hpp"
#include "support/white_sphere.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

constexpr int kSize = 33;  // odd: the centre pixel looks at the sphere's nearest point

test::ServerProcess& server() {
  return test::white_map_server();
}

Reply get(const std::string& path) {
  return test::reply(server().client()->Get(path.c_str()));
}

Reply post_render(const json& body) {
  return test::reply(server().client()->Post("/api/v1/renders", body.dump(), "application/json"));
}

// A white diffuse sphere of radius 1 at the origin, seen from 4 units on -y, on the white map.
json sphere_body(json extra) {
  json body = test::white_sphere_body("white", kSize, 8);
  if (extra.is_object()) body.update(extra);
  return body;
}

// Submits and waits for the render to be done; its id.
std::string rendered(const json& body) {
  const Reply r = post_render(body);
  EXPECT_EQ(r.status, 202) << r.body;
  if (r.status != 202) return "";
  const std::string id = r.body_json()["id"];
  EXPECT_EQ(test::finished_render(*server().client(), id)["status"], "done");
  return id;
}

Image decode(const Reply& r) {
  return read_image({reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()}).image;
}

// The channels of an EXR by name, and its width.
std::map<std::string, std::vector<float>> exr_channels(const std::string& bytes, int& width) {
  test::ExrChannels exr = test::exr_channels(bytes);
  width = exr.width;
  return std::move(exr.channels);
}

TEST(RenderPassesApi, ATransparentRenderHasAlphaZeroInItsCornerAndOneOnTheSphere) {
  const std::string id = rendered(sphere_body({{"background", "transparent"}}));
  const json st = get("/api/v1/renders/" + id).body_json();
  EXPECT_EQ(st["background"], "transparent");
  EXPECT_EQ(st["passes"], json::array({"alpha"}));  // kept for every transparent render
  const int c = kSize / 2;

  const Image alpha = decode(get("/api/v1/renders/" + id + "/image?pass=alpha&format=pfm"));
  ASSERT_EQ(alpha.width(), kSize);
  EXPECT_EQ(alpha.at(0, 0).x, 0.0f);
  EXPECT_EQ(alpha.at(c, c).x, 1.0f);

  const Reply png = get("/api/v1/renders/" + id + "/image?format=png");
  ASSERT_EQ(png.status, 200);
  int w = 0, h = 0, channels = 0;
  stbi_uc* rgba = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.body.data()),
                                        int(png.body.size()), &w, &h, &channels, 0);
  ASSERT_NE(rgba, nullptr);
  EXPECT_EQ(channels, 4);  // RGBA
  EXPECT_EQ(rgba[3], 0);   // the corner: transparent
  EXPECT_EQ(rgba[(size_t(c) * size_t(w) + size_t(c)) * 4 + 3], 255);
  EXPECT_GT(rgba[(size_t(c) * size_t(w) + size_t(c)) * 4], 100);  // the lit sphere, straight colour
  stbi_image_free(rgba);

  int width = 0;
  const auto exr = exr_channels(get("/api/v1/renders/" + id + "/image?format=exr").body, width);
  ASSERT_EQ((std::set<std::string>{"A", "B", "G", "R"}), [&] {
    std::set<std::string> names;
    for (const auto& [name, _] : exr) names.insert(name);
    return names;
  }());
  EXPECT_EQ(exr.at("A")[0], 0.0f);
  EXPECT_EQ(exr.at("R")[0], 0.0f);  // premultiplied: nothing where nothing is
  EXPECT_EQ(exr.at("A")[size_t(c) * size_t(width) + size_t(c)], 1.0f);
}

// 8-bit RGBA of a PNG, WebP or JPEG (RGB: alpha 255), decoded by stb or libwebp.
struct Rgba8 {
  int width = 0, height = 0;
  bool has_alpha = false;
  std::vector<uint8_t> bytes;
  const uint8_t* at(int x, int y) const { return &bytes[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

Rgba8 decode_webp(const Reply& r) {
  Rgba8 out;
  const auto* data = reinterpret_cast<const uint8_t*>(r.body.data());
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(data, r.body.size(), &features) != VP8_STATUS_OK) return out;
  out.has_alpha = features.has_alpha;
  uint8_t* rgba = WebPDecodeRGBA(data, r.body.size(), &out.width, &out.height);
  if (!rgba) return out;
  out.bytes.assign(rgba, rgba + size_t(out.width) * size_t(out.height) * 4);
  WebPFree(rgba);
  return out;
}

Rgba8 decode_stb(const Reply& r) {
  Rgba8 out;
  int channels = 0;
  stbi_uc* rgba = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(r.body.data()), int(r.body.size()),
                                        &out.width, &out.height, &channels, 4);
  if (!rgba) return out;
  out.has_alpha = channels == 4;
  out.bytes.assign(rgba, rgba + size_t(out.width) * size_t(out.height) * 4);
  stbi_image_free(rgba);
  return out;
}

// WebP keeps the alpha of a transparent render, at full size and as a thumbnail; JPEG, which has none,
// shows the PNG's RGBA over white: the corner white, the sphere's centre the PNG's colour.
TEST(RenderPassesApi, ATransparentRenderKeepsItsAlphaInWebpAndIsOverWhiteInJpeg) {
  const std::string id = rendered(sphere_body({{"background", "transparent"}}));
  const int c = kSize / 2;
  const std::string image = "/api/v1/renders/" + id + "/image?format=";
  for (const std::string query : {"webp", "webp&size=17"}) {
    SCOPED_TRACE(query);
    const Reply r = get(image + query);
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_EQ(r.type(), "image/webp");
    const Rgba8 webp = decode_webp(r);
    ASSERT_FALSE(webp.bytes.empty());
    EXPECT_TRUE(webp.has_alpha);
    const int m = webp.width / 2;
    EXPECT_EQ(webp.at(0, 0)[3], 0);  // the map: transparent
    EXPECT_EQ(webp.at(webp.width - 1, webp.height - 1)[3], 0);
    EXPECT_EQ(webp.at(m, m)[3], 255);  // the sphere: opaque
    EXPECT_GT(webp.at(m, m)[0], 100);  // lit, straight colour
  }

  const Rgba8 png = decode_stb(get(image + "png"));
  const Rgba8 jpeg = decode_stb(get(image + "jpeg"));
  ASSERT_EQ(jpeg.width, kSize);
  EXPECT_FALSE(jpeg.has_alpha);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GE(jpeg.at(0, 0)[k], 250);  // white, up to JPEG's loss
    EXPECT_NEAR(jpeg.at(c, c)[k], png.at(c, c)[k], 6);
  }
}

TEST(RenderPassesApi, AlbedoNormalAndDepthOfAWhiteSphereAndEveryPassInOneExr) {
  const std::string id = rendered(sphere_body({{"passes", {"albedo", "normal", "depth"}}}));
  EXPECT_EQ(get("/api/v1/renders/" + id).body_json()["passes"], json::array({"albedo", "normal", "depth"}));
  const int c = kSize / 2;
  const Image albedo = decode(get("/api/v1/renders/" + id + "/image?pass=albedo&format=exr"));
  EXPECT_NEAR(albedo.at(c, c).x, 1.0f, 1e-5f);
  EXPECT_EQ(albedo.at(0, 0).x, 0.0f);
  const Image normal = decode(get("/api/v1/renders/" + id + "/image?pass=normal&format=pfm"));
  EXPECT_NEAR(normal.at(c, c).y, -1.0f, 1e-3f);  // (p - c) / r at the point facing the camera
  const Image depth = decode(get("/api/v1/renders/" + id + "/image?pass=depth&format=exr"));
  EXPECT_NEAR(depth.at(c, c).x, 3.0f, 1e-3f);  // distance 4 minus radius 1
  EXPECT_TRUE(std::isinf(depth.at(0, 0).x));

  int width = 0;
  const auto all = exr_channels(get("/api/v1/renders/" + id + "/image?pass=all&format=exr").body, width);
  std::set<std::string> names;
  for (const auto& [name, _] : all) names.insert(name);
  EXPECT_EQ(names, (std::set<std::string>{"Albedo.B", "Albedo.G", "Albedo.R", "B", "Depth.Z", "G", "Ns.X",
                                          "Ns.Y", "Ns.Z", "R"}));
  const size_t centre = size_t(c) * size_t(width) + size_t(c);
  EXPECT_NEAR(all.at("Depth.Z")[centre], 3.0f, 1e-3f);
  EXPECT_NEAR(all.at("Ns.Y")[centre], -1.0f, 1e-3f);
  EXPECT_NEAR(all.at("Albedo.G")[centre], 1.0f, 1e-5f);

  // Passes the render did not ask for, and pass=all outside EXR.
  const Reply missing = get("/api/v1/renders/" + id + "/image?pass=alpha");
  EXPECT_EQ(missing.status, 409);
  EXPECT_EQ(missing.body_json()["error"]["code"], "pass_not_rendered");
  EXPECT_EQ(get("/api/v1/renders/" + id + "/image?pass=all&format=png").status, 400);
  EXPECT_EQ(get("/api/v1/renders/" + id + "/image?pass=shadow").status, 400);
  EXPECT_EQ(get("/api/v1/renders/" + id + "/image?pass=normal&format=png").status, 200);
}

TEST(RenderPassesApi, AShadowCatcherUnderTheSphereCarriesItsShadowInAlpha) {
  json body = sphere_body({{"background", "transparent"}, {"spp", 16}});
  body["scene"]["objects"].push_back({{"type", "ground"}, {"shadow_catcher", true}});  // at z = -1
  body["scene"]["camera"] = {{"position", {0, -6, 3}}, {"look_at", {0, 0, -0.5}}, {"fov_deg", 50}};
  const std::string id = rendered(body);
  const Image alpha = decode(get("/api/v1/renders/" + id + "/image?pass=alpha&format=pfm"));
  const Image color = decode(get("/api/v1/renders/" + id + "/image?format=pfm"));
  ASSERT_EQ(alpha.width(), kSize);
  // The sky at the top: nothing. The contact shadow right under the sphere's silhouette: partly opaque
  // black. The ground near the image's bottom corners, far from the sphere: mostly clear.
  EXPECT_EQ(alpha.at(kSize / 2, 0).x, 0.0f);
  float darkest = 0;
  for (int y = kSize / 2; y < kSize; ++y)
    darkest = std::max(darkest, alpha.at(kSize / 2, y).x < 1 ? alpha.at(kSize / 2, y).x : 0.0f);
  EXPECT_GT(darkest, 0.3f);
  EXPECT_LT(alpha.at(0, kSize - 1).x, 0.2f);
  EXPECT_EQ(color.at(0, kSize - 1), (Rgb{0, 0, 0}));  // black, premultiplied: only alpha carries it
}

TEST(RenderPassesApi, BadBackgroundClampPassesAndGroundAreRejectedNamingTheField) {
  const auto field_of = [](const json& body) {
    const Reply r = post_render(body);
    EXPECT_EQ(r.status, 400) << r.body;
    return r.status == 400 ? r.body_json()["error"]["message"].get<std::string>() : "";
  };
  EXPECT_EQ(field_of(sphere_body({{"background", "blue"}})).rfind("field 'background'", 0), 0u);
  EXPECT_EQ(field_of(sphere_body({{"background", {1, -1, 0}}})).rfind("field 'background'", 0), 0u);
  EXPECT_EQ(field_of(sphere_body({{"clamp", 0}})).rfind("field 'clamp'", 0), 0u);
  EXPECT_EQ(field_of(sphere_body({{"passes", {"albedo", "beauty"}}})).rfind("field 'passes[1]'", 0), 0u);
  EXPECT_EQ(field_of(sphere_body({{"passes", {"depth", "depth"}}})).rfind("field 'passes[1]'", 0), 0u);
  json ground = sphere_body({});
  ground["scene"]["objects"].push_back({{"type", "ground"}, {"normal", {0, 0, 1}}});
  EXPECT_EQ(field_of(ground).rfind("field 'scene.objects[1].normal'", 0), 0u);
}

}  // namespace
}  // namespace lp

// The tone_mapping parameter against the real server: a render's pictures default to its request's
// curve (neutral unless given), the query overrides it, every picture endpoint takes it, and a name that
// is no curve is a 400 naming the field. The expected 8-bit values are worked out in each test.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::reply;
using test::Reply;

const test::ServerProcess& server() {
  return test::white_map_server();
}

Reply get(const std::string& path) {
  return reply(server().client()->Get(path.c_str()));
}

// A render of no objects on the white map: every pixel is the map, linear radiance exactly 1.
std::string white_render(const json& extra = json::object()) {
  json body = {
      {"envmap", "white"}, {"scene", {{"objects", json::array()}}}, {"width", 4}, {"height", 2}, {"spp", 1}};
  body.update(extra);
  const Reply r = reply(server().client()->Post("/api/v1/renders", body.dump(), "application/json"));
  EXPECT_EQ(r.status, 202) << r.body;
  if (r.status != 202) return "";
  const std::string id = r.body_json()["id"];
  const auto client = server().client();
  EXPECT_EQ(test::finished_render(*client, id)["status"], "done");
  return id;
}

// The one value every channel of every pixel of a PNG answer has (-1 if they differ or it is no PNG).
int uniform_value(const std::string& path) {
  const Reply r = get(path);
  EXPECT_EQ(r.status, 200) << path << ": " << r.body;
  const test::PngPixels png =
      test::decode_png({reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()});
  if (png.rgb.empty()) return -1;
  for (const uint8_t v : png.rgb)
    if (v != png.rgb[0]) return -1;
  return png.rgb[0];
}

void expect_field_error(const Reply& r, const std::string& field) {
  EXPECT_EQ(r.status, 400) << r.body;
  if (r.status != 400) return;
  const json e = r.body_json()["error"];
  EXPECT_EQ(e["code"], "invalid_field") << r.body;
  EXPECT_EQ(e["message"].get<std::string>().rfind("field '" + field + "': ", 0), 0u) << r.body;
}

// Radiance 1 by default (neutral): PBR Neutral compresses the peak 1 - 0.04 = 0.96 to
// 1 - 0.24^2 / (0.96 + 0.24 - 0.76) = 0.869091, sRGB 0.94009, 8-bit 240; `standard` clips at 1: 255. One
// stop down (0.5): neutral 0.46, sRGB 0.70838, 181; standard 0.5, sRGB 0.73536, 188.
TEST(ToneMappingApi, ARenderImageDefaultsToNeutralAndTheQueryOverrides) {
  const std::string image = "/api/v1/renders/" + white_render() + "/image?format=png";
  EXPECT_EQ(uniform_value(image), 240);
  EXPECT_EQ(uniform_value(image + "&tone_mapping=neutral"), 240);
  EXPECT_EQ(uniform_value(image + "&tone_mapping=standard"), 255);
  EXPECT_EQ(uniform_value(image + "&exposure=-1"), 181);
  EXPECT_EQ(uniform_value(image + "&exposure=-1&tone_mapping=standard"), 188);
}

// The request's `tone_mapping` is the default of its pictures. Radiance 1: agx 0.590196 (three.js's
// AgX), sRGB 0.79359, 202; reinhard 1 / 2 = 0.5, 188; aces 0.763397, 226.
TEST(ToneMappingApi, TheRenderRequestsCurveIsTheDefaultOfItsPictures) {
  const std::string image =
      "/api/v1/renders/" + white_render({{"tone_mapping", "agx"}}) + "/image?format=png";
  EXPECT_EQ(uniform_value(image), 202);
  EXPECT_EQ(uniform_value(image + "&tone_mapping=reinhard"), 188);
  EXPECT_EQ(uniform_value(image + "&tone_mapping=aces"), 226);
}

// The map's own pictures default to standard: the white map is 255, 240 through neutral.
TEST(ToneMappingApi, MapPicturesDefaultToStandard) {
  EXPECT_EQ(uniform_value("/api/v1/envmaps/white/image?format=png"), 255);
  EXPECT_EQ(uniform_value("/api/v1/envmaps/white/image?format=png&tone_mapping=neutral"), 240);
}

TEST(ToneMappingApi, ANameThatIsNoCurveIs400NamingTheField) {
  const std::string id = white_render();
  for (const std::string& path : {"/api/v1/renders/" + id + "/image?tone_mapping=filmic",
                                  std::string("/api/v1/envmaps/white/image?tone_mapping=x"),
                                  std::string("/api/v1/envmaps/white/samples.png?tone_mapping=x"),
                                  std::string("/api/v1/envmaps/white/median-cut.png?tone_mapping=x"),
                                  std::string("/api/v1/envmaps/white/sh.png?tone_mapping=x")}) {
    SCOPED_TRACE(path);
    expect_field_error(get(path), "tone_mapping");
  }
  json body = {{"envmap", "white"}, {"tone_mapping", "filmic"}};
  expect_field_error(reply(server().client()->Post("/api/v1/renders", body.dump(), "application/json")),
                     "tone_mapping");
}

}  // namespace
}  // namespace lp

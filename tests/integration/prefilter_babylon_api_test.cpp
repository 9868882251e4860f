// The prefilter job with "target": "babylon" on the real server: in a white furnace (radiance 1) every
// face of every level of the served .env decodes to 1 and its polynomial is E / pi = 1; the files are
// listed in the job's status and served with their types.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <nlohmann/json.hpp>
#include <string>

#include "engine/image/babylon_env.hpp"
#include "engine/image/rgbd.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/shared_client.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

TEST(PrefilterBabylonApi, AWhiteFurnaceIsOneOnEveryFaceAndInThePolynomial) {
  const std::string map = test::ensure_white_map(test::shared_client(), "babylon_white");
  const Reply r = test::reply(
      test::shared_client().Post(("/api/v1/envmaps/" + map + "/prefilter").c_str(),
                                 R"({"target":"babylon","base_size":16,"samples":64})", "application/json"));
  ASSERT_EQ(r.status, 202) << r.body;
  const json st = test::finished_job(test::shared_client(), r.header("Location"));
  ASSERT_EQ(st["status"], "done") << st;
  EXPECT_EQ(st["target"], "babylon");
  ASSERT_EQ(st["files"].size(), 2u) << st;
  EXPECT_EQ(st["files"][0]["name"], "babylon_white.env");
  EXPECT_EQ(st["files"][1]["name"], "manifest.json");

  const Reply file = test::shared_get(st["files"][0]["url"]);
  ASSERT_EQ(file.status, 200) << file.body;
  EXPECT_EQ(file.type(), "application/octet-stream");
  const BabylonEnv env = read_babylon_env(std::vector<uint8_t>(file.body.begin(), file.body.end()));
  EXPECT_EQ(env.width, 16);
  ASSERT_EQ(env.specular.size(), 5u * 6);
  for (const auto& png : env.specular) {
    int w = 0, h = 0, channels = 0;
    uint8_t* pixels = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr);
    for (int i = 0; i < w * h; ++i) {
      const Rgb c = decode_rgbd({pixels[4 * i], pixels[4 * i + 1], pixels[4 * i + 2], pixels[4 * i + 3]});
      EXPECT_NEAR(c.x, 1, 6e-3);  // RGBD's 8 bits
      EXPECT_NEAR(c.z, 1, 6e-3);
    }
    stbi_image_free(pixels);
  }
  ASSERT_TRUE(env.irradiance);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(env.irradiance->xx[c], 1, 1e-6);
    EXPECT_NEAR(env.irradiance->zz[c], 1, 1e-6);
    EXPECT_NEAR(env.irradiance->y[c], 0, 1e-6);
    EXPECT_NEAR(env.irradiance->xy[c], 0, 1e-6);
  }
  const Reply manifest = test::shared_get(st["files"][1]["url"]);
  ASSERT_EQ(manifest.status, 200);
  EXPECT_EQ(manifest.body_json()["target"], "babylon");
}

}  // namespace
}  // namespace lp

// GET /api/v1/prefilters/{id}/levels/{n}.png on the real server: every level of a finished chain as a
// picture of the level's size whose pixels are the level's values (read from its EXR file) tone mapped,
// and the refusals: a level the chain lacks, a bad exposure, a job that has not finished.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/render_polling.hpp"
#include "support/shared_client.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

using test::shared_client;
using test::shared_get;

std::span<const uint8_t> bytes_of(const Reply& r) {
  return {reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()};
}

// The status of a finished job of `map`: a new one (202), or one another test left for the same pixels
// and parameters (200, reused).
json prefiltered(const std::string& map, const std::string& body) {
  const Reply r = test::reply(
      shared_client().Post(("/api/v1/envmaps/" + map + "/prefilter").c_str(), body, "application/json"));
  EXPECT_TRUE(r.status == 202 || r.status == 200) << r.body;
  return test::finished_job(shared_client(), r.header("Location"));
}

// The same of the white map (radiance 1 everywhere).
json white_chain(const std::string& body) {
  const Reply upload = test::upload_white_map(shared_client(), "level_png_white");
  EXPECT_TRUE(upload.status == 201 || upload.status == 409) << upload.body;
  return prefiltered("level_png_white", body);
}

std::string level_url(const json& status, const std::string& level) {
  return "/api/v1/prefilters/" + status["id"].get<std::string>() + "/levels/" + level + ".png";
}

TEST(PrefilterLevelPng, EveryLevelIsItsExrValuesToneMapped) {
  const json st = prefiltered("forest_exr", R"({"levels":4,"base_size":64,"samples":32,"format":"exr"})");
  ASSERT_EQ(st["status"], "done") << st;
  for (int n = 0; n < 4; ++n) {
    SCOPED_TRACE(n);
    // Gamma 1 and exposure -1: a pixel is 255 min(1, v / 2), rounded; 1 of slack for the rounding.
    const Reply png = shared_get(level_url(st, std::to_string(n)) + "?exposure=-1&gamma=1");
    ASSERT_EQ(png.status, 200) << png.body;
    EXPECT_EQ(png.type(), "image/png");
    const test::PngPixels pixels = test::decode_png(bytes_of(png));
    EXPECT_EQ(pixels.width, st["level_info"][n]["width"]);
    EXPECT_EQ(pixels.height, st["level_info"][n]["height"]);
    const Reply exr = shared_get(st["files"][n]["url"]);
    ASSERT_EQ(exr.status, 200);
    const Image level = read_exr(bytes_of(exr), {});
    ASSERT_EQ(pixels.rgb.size(), level.data().size());
    for (size_t i = 0; i < pixels.rgb.size(); ++i) {
      const double expected = 255.0 * std::min(1.0, double(level.data()[i]) / 2);
      ASSERT_NEAR(pixels.rgb[i], expected, 1.0) << "value " << i;
    }
  }
}

TEST(PrefilterLevelPng, AWhiteChainIsWhiteAndItsPicturesAreCachedResults) {
  const json st = white_chain(R"({"levels":3,"base_size":16,"samples":16})");
  ASSERT_EQ(st["status"], "done") << st;
  const Reply last = shared_get(level_url(st, "2"));  // the sRGB curve at exposure 0: radiance 1 is 255
  ASSERT_EQ(last.status, 200) << last.body;
  const test::PngPixels pixels = test::decode_png(bytes_of(last));
  EXPECT_EQ(pixels.width, 4);
  EXPECT_EQ(pixels.height, 2);
  for (const uint8_t v : pixels.rgb) EXPECT_EQ(v, 255);
  EXPECT_FALSE(last.header("ETag").empty());
  EXPECT_EQ(shared_get(level_url(st, "2")).header("ETag"), last.header("ETag"));
}

TEST(PrefilterLevelPng, ALevelTheChainLacksIs404AndABadExposureA400) {
  const json st = white_chain(R"({"levels":2,"base_size":16,"samples":16})");
  ASSERT_EQ(st["status"], "done") << st;
  for (const std::string level : {"2", "01", "-1", "1.0", "x", "+1"}) {
    const Reply r = shared_get(level_url(st, level));
    EXPECT_EQ(r.status, 404) << level;
    EXPECT_EQ(r.body_json()["error"]["code"], "not_found") << level;
  }
  EXPECT_NE(shared_get(level_url(st, "2")).body_json()["error"]["message"].get<std::string>().find("0 to 1"),
            std::string::npos);
  const Reply bright = shared_get(level_url(st, "0") + "?exposure=100");
  EXPECT_EQ(bright.status, 400);
  EXPECT_EQ(bright.body_json()["error"]["code"], "invalid_field");
  const Reply unknown = shared_get(level_url(st, "0") + "?format=exr");
  EXPECT_EQ(unknown.status, 400);
  EXPECT_EQ(shared_get("/api/v1/prefilters/0123456789abcdef/levels/0.png").status, 404);
}

TEST(PrefilterLevelPng, AJobThatHasNotFinishedHasNoPicturesYet) {
  const Reply long_job = test::reply(shared_client().Post("/api/v1/envmaps/forest_exr/prefilter",
                                                          R"({"levels":11,"base_size":2048,"samples":1024})",
                                                          "application/json"));
  ASSERT_EQ(long_job.status, 202) << long_job.body;
  const std::string url = long_job.header("Location");
  const Reply early = shared_get(url + "/levels/0.png");
  EXPECT_EQ(early.status, 409);
  EXPECT_EQ(early.body_json()["error"]["code"], "no_image_yet");
  test::reply(shared_client().Delete(url.c_str()));
  EXPECT_EQ(test::finished_job(shared_client(), url)["status"], "cancelled");
  EXPECT_EQ(shared_get(url + "/levels/0.png").status, 409);
}

}  // namespace
}  // namespace lp

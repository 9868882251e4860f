// POST /api/v1/envmaps/{id}/sun on the real server: a map with a sun of known direction and power
// (support/sunny_map.hpp) gives it back, the residual map is registered, listed and usable (samples,
// a render), powers add up exactly, a map without a sun says so, renders take `sun: extract`, and bad
// input is refused with its field named.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/constants.hpp"
#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/shared_client.hpp"
#include "support/sunny_map.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

using test::shared_client;
using test::shared_get;

Reply post_sun(const std::string& map, const std::string& body) {
  return test::reply(
      shared_client().Post(("/api/v1/envmaps/" + map + "/sun").c_str(), body, "application/json"));
}

Reply upload(const std::string& name, const Image& image) {
  const auto pfm = write_pfm(image);
  return test::reply(shared_client().Post(("/api/v1/envmaps?name=" + name).c_str(),
                                          reinterpret_cast<const char*>(pfm.data()), pfm.size(),
                                          "application/octet-stream"));
}

// The smooth sky with a sun of 1.5 degrees at theta 60, phi 120, uploaded once as "sunny"; its sun.
const test::AddedSun& sunny() {
  static const test::AddedSun sun = [] {
    Image image = test::latlong_image(512, test::smooth_sky);
    const test::AddedSun added = test::add_sun(image, 60, 120, 1.5, Rgb{4000, 3600, 3000});
    const Reply r = upload("sunny", image);
    EXPECT_TRUE(r.status == 201 || r.status == 409) << r.body;
    return added;
  }();
  return sun;
}

Direction direction_of(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

void expect_field_error(const Reply& r, const std::string& field) {
  EXPECT_EQ(r.status, 400) << r.body;
  const json e = r.body_json()["error"];
  EXPECT_EQ(e["code"], "invalid_field") << r.body;
  EXPECT_EQ(e["message"].get<std::string>().rfind("field '" + field + "'", 0), 0u) << r.body;
}

TEST(SunApi, FindsTheSunOfAMapAndRegistersTheResidual) {
  const test::AddedSun& added = sunny();
  const Reply r = post_sun("sunny", "");
  ASSERT_EQ(r.status, 200) << r.body;
  const json j = r.body_json();
  ASSERT_TRUE(j["found"].get<bool>()) << r.body;
  EXPECT_LT(angle_between(direction_of(j["direction"]), added.axis), kPi / 256);  // one pixel
  const json power = j["power"];
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(power["sun"][c].get<double>() / added.power[c], 1.0, 0.01);
    EXPECT_EQ(power["residual"][c].get<double>() + power["sun"][c].get<double>(),
              power["map"][c].get<double>());
    // The irradiance of a uniform disc: the power times (1 + cos r) / 2.
    const double r_sun = j["angular_radius"].get<double>();
    EXPECT_NEAR(j["irradiance"][c].get<double>(), power["sun"][c].get<double>() * (1 + std::cos(r_sun)) / 2,
                1e-9);
    EXPECT_NEAR(j["color"][c].get<double>() * j["solid_angle"].get<double>(), power["sun"][c].get<double>(),
                1e-9);
  }
  EXPECT_NEAR(j["angular_radius"].get<double>(), added.radius, 0.2 * added.radius);
  EXPECT_NEAR(j["theta"].get<double>(), kPi / 3, kPi / 256);
  EXPECT_NEAR(j["phi"].get<double>(), 2 * kPi / 3, 2 * kPi / 256);
  EXPECT_EQ(j["residual"], "sunny-sun");
  EXPECT_EQ(j["parameters"]["threshold"], 0.05);

  // Listed with its source, and holding the residual's power.
  const json meta = shared_get("/api/v1/envmaps/sunny-sun").body_json();
  EXPECT_EQ(meta["format"], "residual");
  EXPECT_EQ(meta["source"], "sun:sunny");
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(meta["power"][c].get<double>(), power["residual"][c].get<double>(),
                1e-6 * power["map"][c].get<double>());
  EXPECT_LT(meta["max_luminance"].get<double>(), 2.0);  // only the sky is left
  const json list = shared_get("/api/v1/envmaps").body_json();
  bool listed = false;
  for (const json& m : list["envmaps"]) listed = listed || m["id"] == "sunny-sun";
  EXPECT_TRUE(listed);
  const Reply samples = test::reply(shared_client().Post("/api/v1/envmaps/sunny-sun/samples",
                                                         R"({"count":16,"seed":1})", "application/json"));
  EXPECT_EQ(samples.status, 200) << samples.body;

  // Asked again: the same residual, from the cache.
  const json again = post_sun("sunny", "{}").body_json();
  EXPECT_TRUE(again["cached"].get<bool>());
  EXPECT_EQ(again["residual"], "sunny-sun");
  EXPECT_EQ(again["power"], power);
}

TEST(SunApi, OtherParametersReplaceTheResidual) {
  sunny();
  ASSERT_EQ(post_sun("sunny", "").status, 200);
  const Reply r = post_sun("sunny", R"({"threshold":0.5,"max_radius_deg":3,"min_share":0.5})");
  ASSERT_EQ(r.status, 200) << r.body;
  const json j = r.body_json();
  EXPECT_TRUE(j["found"].get<bool>());
  EXPECT_FALSE(j["cached"].get<bool>());
  EXPECT_EQ(j["residual"], "sunny-sun");
  EXPECT_EQ(j["parameters"]["max_radius_deg"], 3.0);
  const json meta = shared_get("/api/v1/envmaps/sunny-sun").body_json();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(meta["power"][c].get<double>(), j["power"]["residual"][c].get<double>(),
                1e-6 * j["power"]["map"][c].get<double>());
}

TEST(SunApi, AConstantMapHasNoSun) {
  const Reply up = test::upload_white_map(shared_client(), "sun_white");
  ASSERT_TRUE(up.status == 201 || up.status == 409) << up.body;
  const Reply r = post_sun("sun_white", "");
  ASSERT_EQ(r.status, 200) << r.body;
  const json j = r.body_json();
  EXPECT_FALSE(j["found"].get<bool>());
  EXPECT_NE(j["reason"].get<std::string>().find("not compact"), std::string::npos) << j["reason"];
  EXPECT_TRUE(j["residual"].is_null());
  EXPECT_FALSE(j.contains("direction"));
  EXPECT_EQ(j["power"]["residual"], j["power"]["map"]);
  EXPECT_EQ(j["power"]["sun"], json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(shared_get("/api/v1/envmaps/sun_white-sun").status, 404);
}

TEST(SunApi, BadInput) {
  sunny();
  expect_field_error(post_sun("sunny", R"({"threshold":0})"), "threshold");
  expect_field_error(post_sun("sunny", R"({"threshold":1.5})"), "threshold");
  expect_field_error(post_sun("sunny", R"({"max_radius_deg":"5"})"), "max_radius_deg");
  expect_field_error(post_sun("sunny", R"({"max_radius_deg":31})"), "max_radius_deg");
  expect_field_error(post_sun("sunny", R"({"min_share":-0.1})"), "min_share");
  expect_field_error(post_sun("sunny", R"({"min_contrast":0.5})"), "min_contrast");
  expect_field_error(post_sun("sunny", R"({"radius":2})"), "radius");
  const Reply not_json = post_sun("sunny", "threshold=0.1");
  EXPECT_EQ(not_json.status, 400);
  EXPECT_EQ(not_json.body_json()["error"]["code"], "invalid_json");
  const Reply missing = post_sun("no_such_map", "");
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.body_json()["error"]["code"], "not_found");
}

TEST(SunApi, AMapOfTheResidualsNameFromElsewhereIsAConflict) {
  Image image = test::latlong_image(128, test::smooth_sky);
  test::add_sun(image, 70, 300, 4, Rgb{500, 500, 500});
  ASSERT_EQ(upload("sun_taken", image).status, 201);
  ASSERT_EQ(upload("sun_taken-sun", test::latlong_image(128, test::smooth_sky)).status, 201);
  const Reply r = post_sun("sun_taken", "");
  EXPECT_EQ(r.status, 409) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "conflict");
}

TEST(SunApi, RendersExtractTheSunAndEchoIt) {
  sunny();
  for (const std::string sun : {"extract", "none"}) {
    const json body = {{"envmap", "sunny"},
                       {"scene", {{"preset", "materials"}}},
                       {"lighting", {{"mode", "envmap"}, {"sun", sun}}},
                       {"width", 24},
                       {"height", 16},
                       {"spp", 4}};
    const Reply r = test::reply(shared_client().Post("/api/v1/renders", body.dump(), "application/json"));
    ASSERT_EQ(r.status, 202) << r.body;
    const json done = test::finished_render(shared_client(), r.body_json()["id"]);
    EXPECT_EQ(done["status"], "done") << done.dump();
    EXPECT_EQ(done["lighting_sun"], sun);
    EXPECT_EQ(done["lighting_sun_parameters"], post_sun("sunny", "").body_json()["parameters"]);
  }
  const json wrong = {{"envmap", "sunny"}, {"lighting", {{"mode", "bsdf"}, {"sun", "extract"}}}};
  expect_field_error(test::reply(shared_client().Post("/api/v1/renders", wrong.dump(), "application/json")),
                     "lighting.sun");
}

// The render request carries the sun's parameters: they reach the extraction (a min_share above the
// sun's share leaves no sun to extract) and are echoed; a bad one is refused with its path named.
TEST(SunApi, RendersCarryTheSunParameters) {
  sunny();
  const json params = {{"min_share", 0.99}, {"min_contrast", 20}};
  const json body = {{"envmap", "sunny"},
                     {"lighting", {{"mode", "envmap"}, {"sun", "extract"}, {"sun_parameters", params}}},
                     {"width", 16},
                     {"height", 8},
                     {"spp", 1}};
  const Reply r = test::reply(shared_client().Post("/api/v1/renders", body.dump(), "application/json"));
  ASSERT_EQ(r.status, 202) << r.body;
  const json done = test::finished_render(shared_client(), r.body_json()["id"]);
  EXPECT_EQ(done["lighting_sun_parameters"]["min_share"], 0.99);
  EXPECT_EQ(done["lighting_sun_parameters"]["min_contrast"], 20);
  EXPECT_EQ(done["lighting_sun_parameters"]["threshold"],
            post_sun("sunny", "").body_json()["parameters"]["threshold"]);
  json bad = body;
  bad["lighting"]["sun_parameters"] = {{"min_contrast", 0}};
  expect_field_error(test::reply(shared_client().Post("/api/v1/renders", bad.dump(), "application/json")),
                     "lighting.sun_parameters.min_contrast");
  bad["lighting"]["sun_parameters"] = {{"size", 1}};
  expect_field_error(test::reply(shared_client().Post("/api/v1/renders", bad.dump(), "application/json")),
                     "lighting.sun_parameters.size");
}

// The sun and the median-cut lights as files for other tools, from the API.
TEST(SunApi, LightsForOtherTools) {
  sunny();
  const auto post = [](const std::string& path) {
    return test::reply(shared_client().Post(path.c_str(), "", "application/json"));
  };
  const Reply gltf = post("/api/v1/envmaps/sunny/sun?format=gltf");
  ASSERT_EQ(gltf.status, 200) << gltf.body;
  const json doc = gltf.body_json();
  const json info = shared_get("/api/v1/envmaps/sunny").body_json();
  EXPECT_EQ(doc["asset"]["extras"]["upper_hemisphere_illuminance"], info["illuminance"]);
  const json sun = post_sun("sunny", "").body_json();
  const json& light = doc["extensions"]["KHR_lights_punctual"]["lights"][0];
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(light["intensity"].get<double>() * light["color"][c].get<double>(),
                sun["irradiance"][c].get<double>(), 1e-9 * sun["irradiance"][c].get<double>());
  const Reply usd = post("/api/v1/envmaps/sunny/median-cut?format=usd");
  ASSERT_EQ(usd.status, 200) << usd.body;
  size_t prims = 0;
  for (size_t at = usd.body.find("def DistantLight"); at != std::string::npos;
       at = usd.body.find("def DistantLight", at + 1))
    ++prims;
  EXPECT_EQ(prims, 64u);
  expect_field_error(post("/api/v1/envmaps/sunny/sun?format=fbx"), "format");
  expect_field_error(post("/api/v1/envmaps/sunny/median-cut?format=gltf&frame=world"), "frame");
  EXPECT_EQ(post("/api/v1/envmaps/sunny/median-cut?format=mitsuba&frame=world").status, 200);
}

TEST(SunApi, TheResidualRendersLikeAnyMap) {
  sunny();
  ASSERT_EQ(post_sun("sunny", "").status, 200);
  const json body = {{"envmap", "sunny-sun"}, {"width", 16}, {"height", 16}, {"spp", 2}};
  const Reply r = test::reply(shared_client().Post("/api/v1/renders", body.dump(), "application/json"));
  ASSERT_EQ(r.status, 202) << r.body;
  EXPECT_EQ(test::finished_render(shared_client(), r.body_json()["id"])["status"], "done");
}

}  // namespace
}  // namespace lp

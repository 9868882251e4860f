// Projections on the real server: GET /api/v1/envmaps/{id}/image?projection=... answers each projection
// in its shape and content type, a white map stays exactly white, the power of a real map is kept; maps
// uploaded as a cross, a cube strip or a square come back as lat-long maps of the original's power, and
// stay so across a restart; bad values are 400s naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/projection/projection_texels.hpp"
#include "engine/projection/reproject.hpp"
#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

Reply get(const std::string& path) {
  return test::reply(test::shared_server().client()->Get(path.c_str()));
}

Reply upload(httplib::Client& client, const std::string& query, const std::vector<uint8_t>& file) {
  return test::reply(client.Post(("/api/v1/envmaps?" + query).c_str(),
                                 reinterpret_cast<const char*>(file.data()), file.size(),
                                 "application/octet-stream"));
}

Image decoded(const Reply& r) {
  return read_image(std::span(reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size())).image;
}

double relative_error(Rgb a, Rgb b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(a[c]) - b[c]) / double(b[c]));
  return worst;
}

Rgb json_rgb(const json& j) {
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

const std::string& white() {
  static const std::string name = test::ensure_white_map(*test::shared_server().client(), "projection_white");
  return name;
}

// forest_exr is 256 x 128: by default faces of 64 and squares of 128.
TEST(ProjectionApi, EachProjectionAnswersItsShapeAndType) {
  struct Case {
    std::string query, type;
    int width, height;
  };
  const Case cases[] = {{"", "image/png", 256, 128},
                        {"projection=latlong&format=exr", "image/x-exr", 256, 128},
                        {"projection=cube", "image/png", 384, 64},
                        {"projection=cube&format=exr", "image/x-exr", 384, 64},
                        {"projection=cube&face=py&size=32&format=pfm", "image/x-portable-floatmap", 32, 32},
                        {"projection=cross&format=hdr", "image/vnd.radiance", 256, 192},
                        {"projection=cross&size=16", "image/png", 64, 48},
                        {"projection=octahedral&format=exr", "image/x-exr", 128, 128},
                        {"projection=equal-area&size=50&format=pfm", "image/x-portable-floatmap", 50, 50}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.query);
    const Reply r = get("/api/v1/envmaps/forest_exr/image?" + c.query);
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_EQ(r.type(), c.type);
    if (c.type == "image/png") {
      const test::PngPixels png =
          test::decode_png(std::span(reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()));
      EXPECT_EQ(png.width, c.width);
      EXPECT_EQ(png.height, c.height);
    } else {
      const Image image = decoded(r);
      EXPECT_EQ(image.width(), c.width);
      EXPECT_EQ(image.height(), c.height);
    }
  }
}

TEST(ProjectionApi, AWhiteMapIsWhiteInEveryProjection) {
  for (const std::string p : {"cube", "cross", "octahedral", "equal-area"}) {
    SCOPED_TRACE(p);
    const Reply r = get("/api/v1/envmaps/" + white() + "/image?format=pfm&size=20&projection=" + p);
    ASSERT_EQ(r.status, 200) << r.body;
    const Image image = decoded(r);
    const Projection projection = *parse_enum<Projection>(p);
    const ImageShape shape{image.width(), image.height()};
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const bool empty =
            texel_centre_direction(projection, shape, x, y) == Vec3d{};  // a cross's black cells
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], empty ? 0.0 : 1.0, 1e-6) << x << "," << y;
      }
  }
}

// The power of each projection (sum of radiance times exact texel solid angle) against the map's, and the
// single face against its part of the strip.
TEST(ProjectionApi, ProjectionsKeepThePowerOfARealMap) {
  const Rgb power = json_rgb(get("/api/v1/envmaps/sunrise_exr").body_json()["power"]);
  for (const std::string p : {"cube", "cross", "octahedral", "equal-area"}) {
    const Reply r = get("/api/v1/envmaps/sunrise_exr/image?format=exr&projection=" + p);
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_LT(relative_error(projected_power(decoded(r), *parse_enum<Projection>(p)), power), 1e-4) << p;
  }
  const Image strip = decoded(get("/api/v1/envmaps/sunrise_exr/image?format=exr&projection=cube"));
  const Image nz = decoded(get("/api/v1/envmaps/sunrise_exr/image?format=exr&projection=cube&face=nz"));
  ASSERT_EQ(nz.width(), 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) ASSERT_EQ(nz.at(x, y), strip.at(5 * 64 + x, y));
}

// The round trip through uploads: a map converted to a cross (or strip, or square) and uploaded
// with its projection reads back as a lat-long map of the original's size and power.
TEST(ProjectionApi, AConvertedMapUploadedInItsProjectionReadsBackToTheOriginalPower) {
  const EnvMap original(read_image_file(test::envmap_path("courtyard.exr")).image);
  auto client = test::shared_server().client();
  for (const auto& [name, projection] : {std::pair{"cross", Projection::Cross},
                                         {"cube", Projection::Cube},
                                         {"equal-area", Projection::EqualArea},
                                         {"octahedral", Projection::Octahedral}}) {
    SCOPED_TRACE(name);
    const Image projected = reproject(original.image(), Projection::LatLong, projection,
                                      equivalent_size(projection, original.width()));
    const std::string id = std::string("courtyard_") + name;
    const Reply r = upload(*client, "name=" + id + "&projection=" + name, write_exr(projected));
    ASSERT_EQ(r.status, 201) << r.body;
    const json meta = r.body_json();
    EXPECT_EQ(meta["source_projection"], name);
    EXPECT_EQ(meta["width"], 256);
    EXPECT_EQ(meta["height"], 128);
    EXPECT_LT(relative_error(json_rgb(meta["power"]), original.power()), 1e-4);
    const Image back = decoded(get("/api/v1/envmaps/" + id + "/image?format=pfm"));
    EXPECT_LT(relative_error(EnvMap::power_of(back), original.power()), 1e-4);
  }
}

TEST(ProjectionApi, BadValuesAreRefusedNamingTheParameter) {
  struct Case {
    std::string query, field;
  };
  const Case cases[] = {{"projection=mercator", "projection"},
                        {"projection=cube&size=1", "size"},
                        {"projection=cube&size=8193", "size"},
                        {"projection=cube&size=big", "size"},
                        {"size=64", "size"},
                        {"projection=latlong&size=64", "size"},
                        {"projection=cross&face=px", "face"},
                        {"projection=cube&face=top", "face"},
                        {"projection=cube&size=4096", "size"}};  // 6 x 4096^2 pixels, over --max-pixels
  for (const Case& c : cases) {
    SCOPED_TRACE(c.query);
    const Reply r = get("/api/v1/envmaps/forest_exr/image?" + c.query);
    ASSERT_EQ(r.status, 400) << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field");
    EXPECT_NE(r.body_json()["error"]["message"].get<std::string>().find("'" + c.field + "'"),
              std::string::npos)
        << r.body;
  }
}

TEST(ProjectionApi, AnUploadWhoseShapeDoesNotFitItsProjectionIsRefused) {
  auto client = test::shared_server().client();
  const auto forest = test::read_bytes(test::envmap_path("forest.exr"));  // 256 x 128
  for (const std::string p : {"cross", "cube", "octahedral", "equal-area", "sphere"}) {
    SCOPED_TRACE(p);
    const Reply r = upload(*client, "name=misfit&projection=" + p, forest);
    ASSERT_EQ(r.status, 400) << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field");
    EXPECT_NE(r.body_json()["error"]["message"].get<std::string>().find("'projection'"), std::string::npos);
  }
  EXPECT_EQ(get("/api/v1/envmaps/misfit").status, 404);
  const Reply message = upload(*client, "name=misfit&projection=cross", forest);
  EXPECT_NE(message.body_json()["error"]["message"].get<std::string>().find("4:3"), std::string::npos)
      << message.body;
}

TEST(ProjectionApi, AMapUploadedAsACrossIsStillOneAfterARestart) {
  test::TempDir state;
  const Image cross = reproject(read_image_file(test::envmap_path("studio.exr")).image, Projection::LatLong,
                                Projection::Cross, 32);
  json before;
  {
    test::ServerProcess server({"--state-dir", state.path().string()});
    const Reply r = upload(*server.client(), "name=studio_cross&projection=cross", write_pfm(cross));
    ASSERT_EQ(r.status, 201) << r.body;
    before = r.body_json();
  }
  test::ServerProcess restarted({"--state-dir", state.path().string()});
  const Reply r = test::reply(restarted.client()->Get("/api/v1/envmaps/studio_cross"));
  ASSERT_EQ(r.status, 200) << r.body;
  const json after = r.body_json();
  EXPECT_EQ(after["source_projection"], "cross");
  EXPECT_EQ(after["width"], 128);
  EXPECT_EQ(after["power"], before["power"]);
}

}  // namespace
}  // namespace lp

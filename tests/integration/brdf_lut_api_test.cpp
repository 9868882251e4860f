// GET /api/v1/brdf-lut on the real server: the table in each format equals the engine's, the layout,
// caching, and bad queries.
#include <gtest/gtest.h>

#include <span>
#include <string>

#include "engine/ibl/dfg_lut.hpp"
#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/png_pixels.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using test::Reply;

Reply get(const std::string& path) {
  return test::reply(test::default_server().client()->Get(path.c_str()));
}

std::span<const uint8_t> bytes(const Reply& r) {
  return {reinterpret_cast<const uint8_t*>(r.body.data()), r.body.size()};
}

TEST(BrdfLutApi, TheExrIsTheEnginesTable) {
  const Reply r = get("/api/v1/brdf-lut?size=32");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type(), "image/x-exr");
  EXPECT_EQ(r.header("Cache-Control").rfind("max-age=", 0), 0u);
  const Image image = read_image(bytes(r)).image;
  ASSERT_EQ(image.width(), 32);
  ASSERT_EQ(image.height(), 32);
  const DfgLut lut = make_dfg_lut(32, false);
  for (int y = 0; y < 32; y += 7)
    for (int x = 0; x < 32; x += 5) {
      EXPECT_FLOAT_EQ(image.at(x, y).x, float(lut.at(x, y).x));
      EXPECT_FLOAT_EQ(image.at(x, y).y, float(lut.at(x, y).y));
      EXPECT_EQ(image.at(x, y).z, 0.0f);
    }
  // The smoothest row at normal incidence: scale + bias = 1.
  EXPECT_NEAR(image.at(31, 0).x + image.at(31, 0).y, 1.0, 1e-3);
}

TEST(BrdfLutApi, MultiscatterAndPngLayouts) {
  const Image single = read_image(bytes(get("/api/v1/brdf-lut?size=16"))).image;
  const Image ms = read_image(bytes(get("/api/v1/brdf-lut?size=16&multiscatter=true&format=pfm"))).image;
  ASSERT_EQ(ms.width(), 16);
  EXPECT_FLOAT_EQ(ms.at(3, 9).x, single.at(3, 9).y);
  EXPECT_NEAR(ms.at(3, 9).y, single.at(3, 9).x + single.at(3, 9).y, 1e-6);
  const Reply png = get("/api/v1/brdf-lut?size=16&format=png");
  EXPECT_EQ(png.type(), "image/png");
  const auto pixels = test::decode_png(bytes(png));
  ASSERT_EQ(pixels.width, 16);
  // Linear 8 bits: the channel times 255, rounded.
  const size_t i = (size_t(9) * 16 + 3) * 3;
  EXPECT_NEAR(pixels.rgb[i], single.at(3, 9).x * 255, 1.0);
  EXPECT_NEAR(pixels.rgb[i + 1], single.at(3, 9).y * 255, 1.0);
}

TEST(BrdfLutApi, BadQueriesAre400sNamingTheParameter) {
  for (const std::string query :
       {"size=7", "size=257", "size=1.5", "multiscatter=yes", "format=jpg", "sizes=8"}) {
    const Reply r = get("/api/v1/brdf-lut?" + query);
    EXPECT_EQ(r.status, 400) << query;
    const std::string name = query.substr(0, query.find('='));
    EXPECT_NE(r.body.find("'" + name + "'"), std::string::npos) << r.body;
  }
}

}  // namespace
}  // namespace lp

// The three target through the prefilter job of the real server: no chain is made, the files are served
// with their types, the Ultra HDR JPEG carries the same radiance as the Radiance HDR file, and a chain
// field is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/image/image_io.hpp"
#include "engine/image/ultrahdr.hpp"
#include "support/http_reply.hpp"
#include "support/render_polling.hpp"
#include "support/shared_client.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;
using test::shared_client;
using test::shared_get;

Reply submit(const std::string& body) {
  return test::reply(shared_client().Post("/api/v1/envmaps/forest_exr/prefilter", body, "application/json"));
}

std::vector<uint8_t> file(const json& status, const std::string& name, const std::string& type) {
  for (const json& f : status["files"])
    if (f["name"] == name) {
      const Reply r = shared_get(f["url"]);
      EXPECT_EQ(r.status, 200) << r.body;
      EXPECT_EQ(r.type(), type) << name;
      return {r.body.begin(), r.body.end()};
    }
  ADD_FAILURE() << "no " << name << " in " << status["files"];
  return {};
}

TEST(PrefilterThreeTarget, ServesTheHdrAndUltraHdrMapsOfTheSameRadiance) {
  const Reply r = submit(R"({"target":"three"})");
  ASSERT_EQ(r.status, 202) << r.body;
  const json st = test::finished_job(shared_client(), r.header("Location"));
  ASSERT_EQ(st["status"], "done") << st;
  EXPECT_EQ(st["level_info"], json::array()) << "three.js prefilters at run time: no chain, no levels";
  const Image hdr = read_image(file(st, "forest_exr.hdr", "image/vnd.radiance"), {}).image;
  const DecodedUltraHdr jpg = decode_ultrahdr(file(st, "forest_exr.jpg", "image/jpeg"));
  const json manifest = json::parse(file(st, "manifest.json", "application/json"));
  EXPECT_EQ(manifest["target"], "three");
  ASSERT_EQ(jpg.radiance.width(), hdr.width());
  ASSERT_EQ(jpg.radiance.height(), hdr.height());
  // The gain map's 2 codes (ultrahdr_test.cpp), relative over the offset's floor, and RGBE's step: its
  // 8-bit mantissas share the pixel's exponent, a step of up to 1/128 of the pixel's largest channel.
  const double steps = 2.0 * (jpg.params.gain_map_max - jpg.params.gain_map_min) / 255.0;
  const double relative = std::exp2(steps) - 1.0;
  for (int y = 0; y < hdr.height(); ++y)
    for (int x = 0; x < hdr.width(); ++x) {
      const Rgb want = hdr.at(x, y);
      const double rgbe_step = std::max({want.x, want.y, want.z}) / 128.0;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(jpg.radiance.at(x, y)[c], want[c],
                    relative * (want[c] + jpg.params.offset_hdr) + rgbe_step)
            << x << "," << y;
    }
}

TEST(PrefilterThreeTarget, AChainFieldIsA400NamingIt) {
  const Reply r = submit(R"({"target":"three","levels":4})");
  EXPECT_EQ(r.status, 400) << r.body;
  EXPECT_NE(r.body.find("levels"), std::string::npos) << r.body;
}

}  // namespace
}  // namespace lp

// OpenEXR's standard attributes on what we write, read back with OpenEXR itself: chromaticities (Rec.709
// primaries, D65 white) on every file, envmap latlong on lat-long maps and levels, none on the strip of
// cube faces (not OpenEXR's cube layout).
#include "engine/image/exr_standard_attributes.hpp"

#include <ImfChromaticities.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <fstream>
#include <optional>

#include "api/prefilter_files.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

struct Attributes {
  std::optional<Imf::Envmap> envmap;
  std::optional<Imf::Chromaticities> chromaticities;
};

Attributes read_back(const std::vector<uint8_t>& bytes) {
  const test::TempDir dir;
  const auto path = (dir.path() / "image.exr").string();
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  const Imf::InputFile file(path.c_str());
  Attributes a;
  if (Imf::hasEnvmap(file.header())) a.envmap = Imf::envmap(file.header());
  if (Imf::hasChromaticities(file.header())) a.chromaticities = Imf::chromaticities(file.header());
  return a;
}

void expect_rec709(const std::optional<Imf::Chromaticities>& c) {
  ASSERT_TRUE(c);
  const float want[4][2] = {{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f}};
  const Imath::V2f got[4] = {c->red, c->green, c->blue, c->white};
  for (int i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(got[i].x, want[i][0]) << i;
    EXPECT_FLOAT_EQ(got[i].y, want[i][1]) << i;
  }
}

TEST(ExrStandardAttributes, EveryFileHasRec709AndMapsSayLatLong) {
  Image image(8, 4);
  const Attributes plain = read_back(write_exr(image));
  expect_rec709(plain.chromaticities);
  EXPECT_FALSE(plain.envmap);
  const Attributes map = read_back(write_image_envmap(image, ImageFormat::Exr, {}, ExrEnvmap::LatLong));
  expect_rec709(map.chromaticities);
  ASSERT_TRUE(map.envmap);
  EXPECT_EQ(*map.envmap, Imf::ENVMAP_LATLONG);
  const Attributes cube = read_back(write_exr_envmap(Image(4, 24), ExrEnvmap::Cube));
  ASSERT_TRUE(cube.envmap);
  EXPECT_EQ(*cube.envmap, Imf::ENVMAP_CUBE);
}

TEST(ExrStandardAttributes, PrefilteredLevelsSayTheirLayout) {
  for (const Projection projection : {Projection::LatLong, Projection::Cube}) {
    api::PrefilterRequest request;
    request.format = api::PrefilterFormat::Exr;
    request.params.projection = projection;
    request.params.levels = 2;
    request.params.base_size = 8;
    PrefilteredChain chain{request.params, 0, {}};
    for (int i = 0; i < 2; ++i) {
      const ImageShape s = prefilter_level_shape(request.params, i);
      chain.levels.emplace_back(s.width, s.height);
    }
    const Attributes a = read_back(api::encode_prefilter_file(chain, request, "level1.exr"));
    expect_rec709(a.chromaticities);
    EXPECT_EQ(a.envmap.has_value(), projection == Projection::LatLong) << enum_name(projection);
    if (a.envmap) {
      EXPECT_EQ(*a.envmap, Imf::ENVMAP_LATLONG);
    }
  }
}

}  // namespace
}  // namespace lp

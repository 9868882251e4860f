// `lightprobe bake --target gltf`, the real tool: the KTX2 cube read back holds the engine's own chain of
// the map (a cube of the full pyramid, level i at roughness i / (levels - 1)), the sky on glTF's +Y face,
// and the glTF's irradiance coefficients reconstruct the engine's irradiance of the map in glTF's frame;
// EXT_lights_image_based's RGBD PNG faces are that cube in Babylon.js's frame and its coefficients
// Babylon.js's irradiance harmonics.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/image/rgbd.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/sh/sh_basis.hpp"
#include "engine/sh/sh_projection.hpp"
#include "support/cli_run.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Ktx2Texture read_cube(const fs::path& file) {
  const std::string bytes = read_text(file);
  return read_ktx2({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, {});
}

Image read_rgbd_png(const fs::path& file) {
  const std::string bytes = read_text(file);
  int w = 0, h = 0, channels = 0;
  uint8_t* pixels = stbi_load_from_memory(reinterpret_cast<const uint8_t*>(bytes.data()), int(bytes.size()),
                                          &w, &h, &channels, 4);
  if (!pixels || channels != 4) return Image(0, 0);
  Image image = decode_rgbd_pixels(std::span<const uint8_t>(pixels, size_t(w) * size_t(h) * 4), w, h);
  stbi_image_free(pixels);
  return image;
}

class CliBakeGltf : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    const test::CliRun run =
        test::run_cli({"bake", test::envmap_path("sunrise.exr").string(), "--target", "gltf", "--out",
                       dir_->path().string(), "--base-size", "16", "--samples", "64", "--quiet"});
    ASSERT_EQ(run.exit_status, 0) << run.err;
  }
  static void TearDownTestSuite() { delete dir_; }
  static fs::path file(const std::string& name) { return dir_->path() / name; }
  static json read_json(const std::string& name) { return json::parse(read_text(file(name))); }
  static EnvMap map() { return EnvMap(read_image_file(test::envmap_path("sunrise.exr")).image); }

  static test::TempDir* dir_;
};
test::TempDir* CliBakeGltf::dir_ = nullptr;

TEST_F(CliBakeGltf, TheCubeIsTheEnginesFullPyramid) {
  const json gltf = read_json("sunrise.gltf");
  const std::string uri = gltf["images"][0]["uri"];
  EXPECT_EQ(gltf["images"][0]["mimeType"], "image/ktx2");
  const std::string bytes = read_text(file(uri));
  const Ktx2Texture t = read_ktx2({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, {});
  EXPECT_EQ(t.faces, 6u);
  EXPECT_EQ(t.vk_format, 97u);     // VK_FORMAT_R16G16B16A16_SFLOAT
  ASSERT_EQ(t.levels.size(), 5u);  // 16, 8, 4, 2, 1
  PrefilterParams p;
  p.projection = Projection::Cube;
  p.base_size = 16;
  p.levels = 5;
  p.samples = 64;
  const auto chain = prefilter_chain(map(), p);
  ASSERT_TRUE(chain);
  for (int i = 0; i < 5; ++i) {
    const int size = 16 >> i;
    const Image& level = t.levels[size_t(i)];
    ASSERT_EQ(level.width(), size);
    ASSERT_EQ(level.height(), 6 * size);
    const Image& strip = chain->levels[size_t(i)];
    // Face f of the strip (side by side) is face f of the stack (one below the other), to half precision.
    for (int face = 0; face < 6; ++face)
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
          for (int c = 0; c < 3; ++c) {
            const float want = strip.row(y)[3 * (face * size + x) + c];
            EXPECT_NEAR(level.row(face * size + y)[3 * x + c], want, 1e-3f * std::abs(want) + 1e-6f)
                << "level " << i << " face " << face;
          }
  }
  const json manifest = read_json("manifest.json");
  ASSERT_EQ(manifest["roughness_to_lod"]["roughness"].size(), 5u);
  for (int i = 0; i < 5; ++i)
    EXPECT_DOUBLE_EQ(manifest["roughness_to_lod"]["roughness"][i].get<double>(), i / 4.0);
  EXPECT_NEAR(manifest["units"]["illuminance"].get<double>(), upper_hemisphere_illuminance(map()),
              1e-9 * upper_hemisphere_illuminance(map()));
}

// Level 0's +Y face (index 2) holds the sky, its -Y face (index 3) the ground.
TEST_F(CliBakeGltf, TheSkyIsOnPlusY) {
  const std::string bytes = read_text(file("sunrise_radiance.ktx2"));
  const Ktx2Texture t = read_ktx2({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, {});
  const Image& level = t.levels[0];
  const auto face_mean = [&](int face) {
    double sum = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16 * 3; ++x) sum += level.row(face * 16 + y)[x];
    return sum / (16 * 16 * 3);
  };
  const EnvMap m = map();
  const auto& image = m.image();
  const auto row_mean = [&](int y) {
    double sum = 0;
    for (int x = 0; x < image.width() * 3; ++x) sum += image.row(y)[x];
    return sum / (image.width() * 3);
  };
  // The map's top and bottom rows are the zenith and the nadir, the centres of the +Y and -Y faces.
  EXPECT_GT(face_mean(2), face_mean(3));
  EXPECT_GT(row_mean(0), row_mean(image.height() - 1));
}

// irradianceCoefficients at a glTF direction e give the engine's irradiance at the world direction
// (e.x, -e.z, e.y).
TEST_F(CliBakeGltf, TheIrradianceCoefficientsAreTheEnginesInGltfsFrame) {
  const json light = read_json("sunrise.gltf")["extensions"]["KHR_lights_environment"]["lights"][0];
  const json& c = light["irradianceCoefficients"];
  ASSERT_EQ(c.size(), 9u);
  ShCoefficients gltf{3, std::vector<ShRgb>(9)};
  for (size_t j = 0; j < 9; ++j) {
    ASSERT_EQ(c[j].size(), 3u);
    for (size_t ch = 0; ch < 3; ++ch) gltf.rgb[j][ch] = c[j][ch].get<double>();
  }
  const ShCoefficients world = sh_irradiance(project_sh(map().image(), 3));
  const double dirs[][3] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}, {0.6, 0.48, -0.64}};
  for (const auto& e : dirs) {
    const ShRgb want = world.evaluate(e[0], -e[2], e[1]), got = gltf.evaluate(e[0], e[1], e[2]);
    for (size_t ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], want[ch], 1e-9 * std::abs(want[ch]) + 1e-12);
  }
}

// specularImages[level][face] is the KTX2 cube's level in Babylon.js's frame (glTF with x mirrored): its
// +X and -X faces are the KTX2's -X and +X, every face turned by 180 degrees; to RGBD's 8 bits: a channel
// is (c / 255)^2.2 / D with c rounded, so it is off by at most 2.2 (0.5 / 255) / D, D about 1 / the
// brightest channel (1 below 1). Texels above RGBD's range (the sun) saturate and are not compared.
TEST_F(CliBakeGltf, TheImageBasedFacesAreTheCubeInRgbd) {
  const json gltf = read_json("sunrise.gltf");
  EXPECT_EQ(gltf["extensionsUsed"][1], "EXT_lights_image_based");
  EXPECT_EQ(gltf["scenes"][0]["extensions"]["EXT_lights_image_based"]["light"], 0);
  const json& light = gltf["extensions"]["EXT_lights_image_based"]["lights"][0];
  EXPECT_EQ(light["specularImageSize"], 16);
  EXPECT_EQ(light["intensity"], 1.0);
  const Ktx2Texture t = read_cube(file("sunrise_radiance.ktx2"));
  ASSERT_EQ(light["specularImages"].size(), t.levels.size());
  int compared = 0, saturated = 0;
  for (size_t i = 0; i < t.levels.size(); ++i) {
    const int size = 16 >> i;
    ASSERT_EQ(light["specularImages"][i].size(), 6u);
    for (int face = 0; face < 6; ++face) {
      const json& image = gltf["images"][light["specularImages"][i][size_t(face)].get<size_t>()];
      EXPECT_EQ(image["mimeType"], "image/png");
      const Image png = read_rgbd_png(file(image["uri"]));
      ASSERT_EQ(png.width(), size) << image["uri"];
      ASSERT_EQ(png.height(), size) << image["uri"];
      const int ktx_face = face == 0 ? 1 : face == 1 ? 0 : face;
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          const float* want = &t.levels[i].row(ktx_face * size + size - 1 - y)[3 * (size - 1 - x)];
          const float brightest = std::max({want[0], want[1], want[2]});
          if (brightest > 0.99f * kRgbdMaxRange) {
            ++saturated;
            continue;
          }
          ++compared;
          const float step = 2.2f * 0.5f / 255 * std::max(1.0f, brightest) * 1.01f;
          for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(png.row(y)[3 * x + c], want[c], step + 1e-3f * want[c])
                << "level " << i << " face " << face << " texel " << x << ", " << y;
        }
    }
  }
  EXPECT_EQ(compared + saturated, 6 * (256 + 64 + 16 + 4 + 1));
  EXPECT_LT(saturated, compared / 100) << saturated << " saturated texels";
}

// irradianceCoefficients are Babylon.js's SphericalHarmonics of the irradiance: evaluated with its basis
// (its SH3ylmBasisConstants, Condon-Shortley signs, on the terms 1, y, z, x, xy, yz, 3z^2 - 1, xz,
// x^2 - y^2) at Babylon's direction (-x, z, -y) of a world direction (x, y, z), they give the engine's
// irradiance there.
TEST_F(CliBakeGltf, TheImageBasedCoefficientsAreBabylonsIrradiance) {
  const json gltf = read_json("sunrise.gltf");
  const json& c = gltf["extensions"]["EXT_lights_image_based"]["lights"][0]["irradianceCoefficients"];
  ASSERT_EQ(c.size(), 9u);
  const double pi = std::numbers::pi;
  const double k[9] = {std::sqrt(1 / (4 * pi)),  -std::sqrt(3 / (4 * pi)),  std::sqrt(3 / (4 * pi)),
                       -std::sqrt(3 / (4 * pi)), std::sqrt(15 / (4 * pi)),  -std::sqrt(15 / (4 * pi)),
                       std::sqrt(5 / (16 * pi)), -std::sqrt(15 / (4 * pi)), std::sqrt(15 / (16 * pi))};
  const ShCoefficients world = sh_irradiance(project_sh(map().image(), 3));
  const double dirs[][3] = {{0, 0, 1}, {0, 0, -1},         {1, 0, 0},
                            {0, 1, 0}, {0.6, 0.48, -0.64}, {-0.36, 0.48, 0.8}};
  for (const auto& w : dirs) {
    const double x = -w[0], y = w[2], z = -w[1];
    const double terms[9] = {1, y, z, x, x * y, y * z, 3 * z * z - 1, x * z, x * x - y * y};
    const ShRgb want = world.evaluate(w[0], w[1], w[2]);
    for (size_t ch = 0; ch < 3; ++ch) {
      double got = 0;
      for (size_t j = 0; j < 9; ++j) got += c[j][ch].get<double>() * k[j] * terms[j];
      EXPECT_NEAR(got, want[ch], 1e-9 * std::abs(want[ch]) + 1e-12) << "channel " << ch;
    }
  }
}

TEST_F(CliBakeGltf, AFieldTheTargetFixesIsRefusedByName) {
  const std::string map_path = test::envmap_path("sunrise.exr").string();
  const test::TempDir other;
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
           {"--projection", "latlong"}, {"--levels", "4"}, {"--precision", "float"}, {"--format", "exr"}}) {
    const test::CliRun run =
        test::run_cli({"bake", map_path, "--target", "gltf", "--out", other.path().string(), option, value});
    EXPECT_NE(run.exit_status, 0);
    EXPECT_NE(run.err.find("field '" + option.substr(2) + "'"), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace lp

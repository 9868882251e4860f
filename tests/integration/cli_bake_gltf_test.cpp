// `lightprobe bake --target gltf`, the real tool: the KTX2 cube read back holds the engine's own chain of
// the map (a cube of the full pyramid, level i at roughness i / (levels - 1)), the sky on glTF's +Y face,
// and the glTF's irradiance coefficients reconstruct the engine's irradiance of the map in glTF's frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ktx2.hpp"
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

// `lightprobe bake --target unity|unreal|godot`, the real tool, on a map whose colour tells the world
// direction (tests/support/engine_directions.hpp): each file read back (OpenEXR, our HDR reader, the KTX2
// header as the specification lays it out and its ASTC blocks decoded by libastcenc) shows at every texel
// the colour of the world direction the engine samples there, as the engine's own source maps texels to
// directions and through the frame the manifest states; sizes, and the manifest's frame, files and
// import settings.
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/image/astc.hpp"
#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/engine_directions.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kMapWidth = 64, kMapHeight = 32, kFace = 16, kLevels = 3;

json read_json(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return json::parse(text.str());
}

// Bakes the direction map as `target` into dir/out; `chain` adds the chain's options (base 16, 3 levels).
fs::path bake(const test::TempDir& dir, const std::string& target, bool chain) {
  const fs::path map = dir.path() / "dirs.exr";
  const std::vector<uint8_t> exr = write_exr(test::direction_map(kMapWidth, kMapHeight));
  std::ofstream(map, std::ios::binary)
      .write(reinterpret_cast<const char*>(exr.data()), std::streamsize(exr.size()));
  std::vector<std::string> args = {
      "bake", map.string(), "--target", target, "--out", (dir.path() / "out").string(), "-q"};
  if (chain)
    args.insert(args.end(), {"--base-size", std::to_string(kFace), "--levels", std::to_string(kLevels),
                             "--samples", "64"});
  const test::CliRun run = test::run_cli(args);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return dir.path() / "out";
}

// The manifest lists exactly the files beside it (manifest.json aside), with their sizes.
void expect_files_listed(const fs::path& out, const json& manifest) {
  size_t listed = 0;
  for (const json& file : manifest["files"]) {
    const fs::path path = out / file["name"].get<std::string>();
    ASSERT_TRUE(fs::exists(path)) << path;
    EXPECT_EQ(file["bytes"].get<uintmax_t>(), fs::file_size(path)) << path;
    ++listed;
  }
  EXPECT_EQ(listed + 1, size_t(std::distance(fs::directory_iterator(out), fs::directory_iterator())));
}

void expect_frame(const json& manifest, const std::vector<std::vector<double>>& world_to_engine) {
  EXPECT_EQ(manifest["frame"]["world_to_engine"], json(world_to_engine));
  EXPECT_FALSE(manifest["frame"]["sources"].get<std::string>().empty());
}

// OpenEXR's `envmap` of a file ("none" without one), after checking its `chromaticities` are Rec.709's.
std::string envmap_attribute(const fs::path& exr) {
  Imf::InputFile file(exr.string().c_str());
  EXPECT_TRUE(Imf::hasChromaticities(file.header())) << exr;
  if (Imf::hasChromaticities(file.header())) {
    const Imf::Chromaticities c = Imf::chromaticities(file.header());
    EXPECT_NEAR(c.red.x, 0.64f, 1e-4f);
    EXPECT_NEAR(c.green.y, 0.60f, 1e-4f);
    EXPECT_NEAR(c.white.x, 0.3127f, 1e-4f);
  }
  if (!Imf::hasEnvmap(file.header())) return "none";
  return Imf::envmap(file.header()) == Imf::ENVMAP_LATLONG ? "latlong" : "cube";
}

// A KTX2 ASTC cube: its header fields and each level's faces decoded.
struct AstcCube {
  uint32_t vk_format = 0, width = 0, faces = 0, levels = 0;
  std::vector<std::vector<Image>> faces_by_level;
};

AstcCube read_astc_cube(const fs::path& path) {
  const std::vector<uint8_t> bytes = test::read_bytes(path);
  const auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  const auto u64 = [&](size_t at) {
    uint64_t v;
    std::memcpy(&v, bytes.data() + at, 8);
    return v;
  };
  AstcCube cube{u32(12), u32(20), u32(36), u32(40), {}};
  for (uint32_t p = 0; p < cube.levels; ++p) {
    const int n = std::max(1, int(cube.width) >> p);
    const size_t face_bytes = astc_bytes(n, n), offset = size_t(u64(80 + 24 * p));
    std::vector<Image> faces;
    for (size_t f = 0; f < cube.faces; ++f)
      faces.push_back(decompress_astc_hdr({bytes.data() + offset + f * face_bytes, face_bytes}, n, n));
    cube.faces_by_level.push_back(std::move(faces));
  }
  return cube;
}

// Mean over a face of the channels' summed difference from the colour of the direction an engine
// samples there (the GL/Vulkan table in its axes, world_from giving the world direction).
double face_error(const Image& face, int f, Vec3d (*world_from)(Vec3d)) {
  double sum = 0;
  const int n = face.width();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3d d = normalize(test::gl_cube_direction(f, (2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1));
      const Rgb want = test::direction_colour(world_from(d)), got = face.at(i, j);
      sum += std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z);
    }
  return sum / (n * n);
}

// The mean summed error of a face: level 0 resampled to the cube (measured under 0.02 on every face);
// then compressed to ASTC at the targets' fast preset (measured 0.08 to 0.10, about 2% of the colour). A
// face out of place or mirrored is off by 1 or more.
constexpr double kCubeTolerance = 0.02, kAstcTolerance = 0.2;

// Half floats: 2.5 is held to 2^-10 (1e-3 per channel).
constexpr float kHalfTolerance = 4e-3f;

TEST(CliBakeDesktop, GodotPanoramaCubemapAndAstcCubeAreTheMapInGodotsFrame) {
  const test::TempDir dir;
  const fs::path out = bake(dir, "godot", true);
  const json manifest = read_json(out / "manifest.json");
  EXPECT_EQ(manifest["target"], "godot");
  expect_frame(manifest, {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}});
  expect_files_listed(out, manifest);

  const Image pano = read_image_file(out / "dirs_panorama.exr").image;
  ASSERT_EQ(pano.width(), kMapWidth);
  ASSERT_EQ(pano.height(), kMapHeight);
  EXPECT_EQ(test::texels_off_direction(pano, test::godot_panorama_texel, kHalfTolerance), 0);
  EXPECT_NEAR(pano.at(0, 0).z, 2.5f, 0.01f);               // Godot's up, row 0: the sky
  EXPECT_NEAR(pano.at(0, kMapHeight / 2).y, 2.5f, 0.02f);  // Godot's forward -Z, u = 0: the world's +y

  EXPECT_EQ(envmap_attribute(out / "dirs_panorama.exr"), "latlong");
  EXPECT_EQ(envmap_attribute(out / "dirs_cubemap.exr"), "none");  // a 6x1 strip is no OpenEXR cube

  const Image cube = read_image_file(out / "dirs_cubemap.exr").image;
  ASSERT_EQ(cube.width(), 6 * kFace);
  ASSERT_EQ(cube.height(), kFace);
  for (int f = 0; f < 6; ++f) {
    Image face(kFace, kFace);
    for (int j = 0; j < kFace; ++j)
      for (int i = 0; i < kFace; ++i) face.set(i, j, cube.at(f * kFace + i, j));
    EXPECT_LT(face_error(face, f, test::world_from_godot), kCubeTolerance) << "face " << f;
  }

  const AstcCube astc = read_astc_cube(out / "dirs_radiance_astc.ktx2");
  EXPECT_EQ(astc.vk_format, 1000066000u);
  EXPECT_EQ(astc.width, uint32_t(kFace));
  EXPECT_EQ(astc.faces, 6u);
  EXPECT_EQ(astc.levels, uint32_t(kLevels));
  for (int f = 0; f < 6; ++f)
    EXPECT_LT(face_error(astc.faces_by_level[0][size_t(f)], f, test::world_from_godot), kAstcTolerance) << f;

  EXPECT_EQ(manifest["import"]["cubemap"]["slices/arrangement"], "6x1");
  EXPECT_EQ(manifest["import"]["cubemap"]["Import As"], "Cubemap");
  EXPECT_EQ(manifest["roughness_to_lod"]["roughness"], json({0.0, 0.5, 1.0}));
}

TEST(CliBakeDesktop, UnityLatLongAndAstcCubeAreTheMapInUnitysLeftHandedFrame) {
  const test::TempDir dir;
  const fs::path out = bake(dir, "unity", true);
  const json manifest = read_json(out / "manifest.json");
  EXPECT_EQ(manifest["target"], "unity");
  expect_frame(manifest, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}});
  expect_files_listed(out, manifest);

  const Image latlong = read_image_file(out / "dirs_latlong.exr").image;
  ASSERT_EQ(latlong.width(), kMapWidth);
  EXPECT_EQ(test::texels_off_direction(latlong, test::unity_panorama_texel, kHalfTolerance), 0);
  EXPECT_NEAR(latlong.at(kMapWidth / 4, kMapHeight / 2).y, 0.5f, 0.02f);  // Unity's forward +Z: world -y

  EXPECT_EQ(envmap_attribute(out / "dirs_latlong.exr"), "latlong");

  const AstcCube astc = read_astc_cube(out / "dirs_radiance_astc.ktx2");
  EXPECT_EQ(astc.vk_format, 1000066000u);
  EXPECT_EQ(astc.levels, uint32_t(kLevels));
  for (int f = 0; f < 6; ++f)
    EXPECT_LT(face_error(astc.faces_by_level[0][size_t(f)], f, test::world_from_unity), kAstcTolerance) << f;

  const json& import = manifest["import"];
  EXPECT_EQ(import["Texture Shape"], "Cube");
  EXPECT_EQ(import["Mapping"], "Latitude-Longitude Layout (Cylindrical)");
  EXPECT_EQ(import["Convolution Type"], "Specular (Glossy Reflection)");
  EXPECT_EQ(import["file"], "dirs_latlong.exr");
}

TEST(CliBakeDesktop, UnrealLatLongIsTheMapInUnrealsFrameWithoutRotation) {
  const test::TempDir dir;
  const fs::path out = bake(dir, "unreal", false);
  const json manifest = read_json(out / "manifest.json");
  EXPECT_EQ(manifest["target"], "unreal");
  expect_frame(manifest, {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}});
  expect_files_listed(out, manifest);

  // Radiance HDR keeps 8 bits of mantissa under the largest channel's exponent: 2^-6 steps at 2.5.
  const Image latlong = read_image_file(out / "dirs_latlong.hdr").image;
  ASSERT_EQ(latlong.width(), kMapWidth);
  ASSERT_EQ(latlong.height(), kMapHeight);
  EXPECT_EQ(test::texels_off_direction(latlong, test::unreal_panorama_texel, 0.05f), 0);
  EXPECT_NEAR(latlong.at(3 * kMapWidth / 4, kMapHeight / 2).x, 2.5f, 0.03f);  // Unreal's forward +X: world +x
  EXPECT_EQ(manifest["import"]["Sky Light"]["Source Cubemap Angle"], 0.0);

  // Unreal prefilters itself: a chain option is refused.
  const test::CliRun run = test::run_cli({"bake", (dir.path() / "dirs.exr").string(), "--target", "unreal",
                                          "--out", (dir.path() / "other").string(), "--levels", "3"});
  EXPECT_EQ(run.exit_status, 2) << run.err;
  EXPECT_NE(run.err.find("levels"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace lp

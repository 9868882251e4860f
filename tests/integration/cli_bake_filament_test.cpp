// `lightprobe bake MAP --target filament` against Debian's cmgen 1.9.25 (libfilament-tools, a test
// dependency from scripts/setup --test), run on the same map: the KTX1 headers field by field, every
// level's faces texel by texel and their mean colours, and the `sh` numbers.
//
// The two differ by design in one way: cmgen reads a lat-long map with u = 1/2 + atan2(x, z) / 2 pi in
// Filament's y-up frame and then mirrors x (its default), while the product reads it in its z-up world
// (u = phi / 2 pi, phi from +x to +y) and writes the world through glTF's frame, world (x, y, z) =
// Filament (x, z, -y), as a glTF model enters the product. So cmgen's texel in the world direction (x, y,
// z) holds what ours holds in (y, x, z): the test reads ours there.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/image/ktx1.hpp"
#include "engine/projection/cube_face.hpp"
#include "support/cli_run.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* const kCmgen = "/usr/bin/cmgen";

json read_json(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return json::parse(text.str());
}

int run(const std::string& command) {
  return std::system(command.c_str());
}

struct Baked {
  Ktx1Texture ibl, skybox;
  json manifest;
};

// Both bakes of sunrise.exr (a low sun: the hardest case for agreement), once for the whole suite.
struct Bakes {
  test::TempDir dir;
  Ktx1Texture cmgen_ibl, cmgen_skybox, ibl, skybox;
  json manifest;
  std::string cli_err;
};

const Bakes& bakes() {
  static const Bakes* b = [] {
    auto* out = new Bakes;
    const std::string map = test::envmap_path("sunrise.exr").string();
    const fs::path cmgen_dir = out->dir.path() / "cmgen";
    const int status = run(std::string(kCmgen) + " -q --format=ktx --size=256 --ibl-samples=256 -x " +
                           cmgen_dir.string() + " " + map + " > /dev/null 2>&1");
    EXPECT_EQ(status, 0);
    out->cmgen_ibl = read_ktx1(test::read_bytes(cmgen_dir / "cmgen_ibl.ktx"), {});
    out->cmgen_skybox = read_ktx1(test::read_bytes(cmgen_dir / "cmgen_skybox.ktx"), {});
    const fs::path ours = out->dir.path() / "ours";
    const test::CliRun bake = test::run_cli(
        {"bake", map, "--target", "filament", "--out", ours.string(), "--samples", "256", "-q"});
    EXPECT_EQ(bake.exit_status, 0) << bake.err;
    out->cli_err = bake.err;
    out->ibl = read_ktx1(test::read_bytes(ours / "sunrise_ibl.ktx"), {});
    out->skybox = read_ktx1(test::read_bytes(ours / "sunrise_skybox.ktx"), {});
    out->manifest = read_json(ours / "manifest.json");
    return out;
  }();
  return *b;
}

class CliBakeFilament : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kCmgen))
      GTEST_SKIP() << kCmgen << " is missing: install libfilament-tools (scripts/setup --test)";
  }
};

void expect_same_header(const Ktx1Header& ours, const Ktx1Header& theirs) {
  EXPECT_EQ(ours.gl_type, theirs.gl_type);
  EXPECT_EQ(ours.gl_type_size, theirs.gl_type_size);
  EXPECT_EQ(ours.gl_format, theirs.gl_format);
  EXPECT_EQ(ours.gl_internal_format, theirs.gl_internal_format);
  EXPECT_EQ(ours.gl_base_internal_format, theirs.gl_base_internal_format);
  EXPECT_EQ(ours.width, theirs.width);
  EXPECT_EQ(ours.height, theirs.height);
  EXPECT_EQ(ours.depth, theirs.depth);
  EXPECT_EQ(ours.array_elements, theirs.array_elements);
  EXPECT_EQ(ours.faces, theirs.faces);
  EXPECT_EQ(ours.levels, theirs.levels);
}

TEST_F(CliBakeFilament, HeadersAreCmgens) {
  const Bakes& b = bakes();
  expect_same_header(b.ibl.header, b.cmgen_ibl.header);
  expect_same_header(b.skybox.header, b.cmgen_skybox.header);
  EXPECT_EQ(b.ibl.header.levels, 5u);  // 256 down to cmgen's smallest, 16
  EXPECT_EQ(b.ibl.metadata.size(), 1u);
  EXPECT_TRUE(b.ibl.metadata.contains("sh"));
  EXPECT_TRUE(b.skybox.metadata.empty());
}

// The texel of our level that cmgen's texel (face, i, j) shows (see the top of the file).
Rgb ours_at(const Image& ours, int face, int i, int j) {
  const int n = ours.height();
  const Vec3d w = cube_face_direction(face, {(2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1});
  const CubeFacePoint p = cube_face_point({w.y, w.x, w.z});
  const int i2 = std::clamp(int((p.ab.x + 1) / 2 * n), 0, n - 1),
            j2 = std::clamp(int((p.ab.y + 1) / 2 * n), 0, n - 1);
  return ours.at(p.face * n + i2, j2);
}

struct LevelComparison {
  Rgb ours_mean, cmgen_mean;
  double median = 0;  // of |ours - cmgen| / (cmgen + the level's mean), luminance, over the texels
  std::array<double, 6> ours_faces{}, cmgen_faces{};  // mean luminance of each face
  double rms = 0;              // of the per-texel difference of luminance, over the level's mean luminance
  double face_mean_error = 0;  // the largest relative difference of a face's mean luminance
};

double luminance(Rgb c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// `mirrored`: read ours where cmgen's texel shows it (the top of the file), else at the same direction.
LevelComparison compare_level(const Image& ours, const Image& cmgen, bool mirrored = true) {
  LevelComparison out;
  std::vector<double> relative;
  const int n = cmgen.height();
  double sum_sq = 0;
  Vec3 ours_sum{}, cmgen_sum{};
  double weights = 0;
  for (int face = 0; face < kCubeFaces; ++face) {
    double ours_face = 0, cmgen_face = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double w = cube_texel_solid_angle(n, i, j);
        const Rgb a = mirrored ? ours_at(ours, face, i, j) : ours.at(face * n + i, j),
                  c = cmgen.at(face * n + i, j);
        relative.push_back(std::abs(luminance(a) - luminance(c)) / luminance(c));
        ours_sum = ours_sum + a * float(w), cmgen_sum = cmgen_sum + c * float(w), weights += w;
        ours_face += w * luminance(a), cmgen_face += w * luminance(c);
        sum_sq += w * std::pow(luminance(a) - luminance(c), 2);
      }
    out.face_mean_error = std::max(out.face_mean_error, std::abs(ours_face / cmgen_face - 1));
    out.ours_faces[size_t(face)] = ours_face, out.cmgen_faces[size_t(face)] = cmgen_face;
  }
  out.ours_mean = ours_sum * float(1 / weights), out.cmgen_mean = cmgen_sum * float(1 / weights);
  out.rms = std::sqrt(sum_sq / weights) / luminance(out.cmgen_mean);
  std::nth_element(relative.begin(), relative.begin() + relative.size() / 2, relative.end());
  out.median = relative[relative.size() / 2];
  return out;
}

std::array<int, 6> face_ranking(const std::array<double, 6>& means) {
  std::array<int, 6> order{0, 1, 2, 3, 4, 5};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return means[size_t(a)] > means[size_t(b)]; });
  return order;
}

// Tolerances, from the two bakes' known differences: cmgen resamples the lat-long by point samples (its
// level 0 is 2.6% brighter than the map on sunrise, the sun over-weighted; ours keeps the map's power),
// and its filtered importance sampling from box-filtered mips loses energy as roughness grows (7% by
// roughness 1, 8% in blue) where ours keeps the mean. Per texel, the median relative difference of luminance
// is within 6% on the sharp levels and 13% on the roughest (the sun's lobe drawn by different samples);
// reading ours at the same direction instead of the mirrored one is at least 1.4 times worse on every
// level, and the faces rank alike by brightness on every level.
TEST_F(CliBakeFilament, LevelsMatchCmgensTexelByTexel) {
  const Bakes& b = bakes();
  ASSERT_EQ(b.ibl.levels.size(), b.cmgen_ibl.levels.size());
  const double median_tolerance[5] = {0.06, 0.06, 0.08, 0.13, 0.13};
  for (size_t p = 0; p < b.ibl.levels.size(); ++p) {
    SCOPED_TRACE("level " + std::to_string(p));
    const LevelComparison c = compare_level(b.ibl.levels[p], b.cmgen_ibl.levels[p]);
    const LevelComparison same_direction = compare_level(b.ibl.levels[p], b.cmgen_ibl.levels[p], false);
    std::printf(
        "level %zu: mean ours (%.4f %.4f %.4f) cmgen (%.4f %.4f %.4f), median texel difference %.4f "
        "(%.4f unmirrored)\n",
        p, c.ours_mean.x, c.ours_mean.y, c.ours_mean.z, c.cmgen_mean.x, c.cmgen_mean.y, c.cmgen_mean.z,
        c.median, same_direction.median);
    for (int ch = 0; ch < 3; ++ch) {
      const double ratio = c.ours_mean[ch] / c.cmgen_mean[ch];
      EXPECT_GT(ratio, 0.96) << ch;
      EXPECT_LT(ratio, p < 2 ? 1.04 : 1.10) << ch;
      const LevelComparison base = compare_level(b.ibl.levels[0], b.cmgen_ibl.levels[0]);
      EXPECT_NEAR(c.ours_mean[ch], base.ours_mean[ch], 0.005 * base.ours_mean[ch]) << "ours keeps the mean";
    }
    EXPECT_LT(c.median, median_tolerance[p]);
    EXPECT_LT(c.median * 1.4, same_direction.median);
    EXPECT_EQ(face_ranking(c.ours_faces), face_ranking(c.cmgen_faces));
  }
  const LevelComparison sky = compare_level(b.skybox.levels[0], b.cmgen_skybox.levels[0]);
  EXPECT_LT(sky.median, median_tolerance[0]);
  EXPECT_EQ(face_ranking(sky.ours_faces), face_ranking(sky.cmgen_faces));
}

// The numbers, with cmgen's mirrored into our frame. L00 within 3% (cmgen's level 0 is 2.6% brighter,
// above); the other eight within 8% of L00: both are windowed by cmgen's method, but from SH of two
// resamplings of the sun the cut-off lands at 11.4 bands here and near 12.2 in cmgen.
TEST_F(CliBakeFilament, ShIsCmgensInOurFrame) {
  const Bakes& b = bakes();
  std::istringstream ours_text(b.ibl.metadata.at("sh")), cmgen_text(b.cmgen_ibl.metadata.at("sh"));
  double ours[9][3], cm[9][3];
  for (auto& c : ours) ours_text >> c[0] >> c[1] >> c[2];
  for (auto& c : cm) cmgen_text >> c[0] >> c[1] >> c[2];
  for (int ch = 0; ch < 3; ++ch) {
    // cmgen's polynomial at (x, y, z) is ours at the mirrored direction (-z, y, -x) in Filament's frame.
    const double want[9] = {cm[0][ch],
                            cm[1][ch],
                            -cm[3][ch],
                            -cm[2][ch],
                            -cm[5][ch],
                            -cm[4][ch],
                            -0.5 * cm[6][ch] + 0.5 * cm[8][ch],
                            cm[7][ch],
                            1.5 * cm[6][ch] + 0.5 * cm[8][ch]};
    EXPECT_NEAR(ours[0][ch], want[0], 0.03 * want[0]) << ch;
    for (int i = 1; i < 9; ++i) EXPECT_NEAR(ours[i][ch], want[i], 0.08 * want[0]) << i << " " << ch;
  }
}

}  // namespace
}  // namespace lp

namespace lp {
namespace {

TEST_F(CliBakeFilament, ManifestStatesFrameFacesScheduleAndFiles) {
  const json& m = bakes().manifest;
  EXPECT_EQ(m["target"], "filament");
  EXPECT_EQ(m["frame"]["world_to_engine"], json::parse("[[1,0,0],[0,0,1],[0,-1,0]]"));
  EXPECT_EQ(m["face_order"]["faces"], json::parse(R"(["px","nx","py","ny","pz","nz"])"));
  ASSERT_EQ(m["roughness_to_lod"]["levels"], 5);
  for (int i = 0; i < 5; ++i)  // lod = 4 r (2 - r) = i
    EXPECT_NEAR(m["roughness_to_lod"]["roughness"][size_t(i)].get<double>(), 1 - std::sqrt(1 - i / 4.0),
                1e-12);
  EXPECT_EQ(m["files"][0]["name"], "sunrise_ibl.ktx");
  EXPECT_EQ(m["files"][1]["name"], "sunrise_skybox.ktx");
  EXPECT_GT(m["import"]["sh"]["window_cutoff"].get<double>(), 3);
}

TEST(CliBakeFilamentRefusals, BaseSizeIsAPowerOfTwoAndTheChainIsTheTargets) {
  const test::TempDir dir;
  const std::string map = test::envmap_path("forest.exr").string();
  const auto out = (dir.path() / "out").string();
  const test::CliRun size =
      test::run_cli({"bake", map, "--target", "filament", "--out", out, "--base-size", "96"});
  EXPECT_EQ(size.exit_status, 2);
  EXPECT_NE(size.err.find("base_size"), std::string::npos) << size.err;
  EXPECT_NE(size.err.find("power of two"), std::string::npos) << size.err;
  const test::CliRun projection =
      test::run_cli({"bake", map, "--target", "filament", "--out", out, "--projection", "latlong"});
  EXPECT_EQ(projection.exit_status, 2);
  EXPECT_NE(projection.err.find("projection"), std::string::npos) << projection.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "forest_ibl.ktx"));
}

}  // namespace
}  // namespace lp

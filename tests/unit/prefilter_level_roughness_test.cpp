// The roughness schedules of a chain's levels, against values worked out by hand from each engine's
// formula: glTF's lod = r (n - 1), Filament's lod = (n - 1) r (2 - r), Babylon's alpha = 2^(i / 0.8) /
// base_size.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/prefilter/prefilter_params.hpp"

namespace lp {
namespace {

PrefilterParams schedule(LevelRoughness level_roughness, int levels, int base_size = 256) {
  PrefilterParams p;
  p.levels = levels;
  p.base_size = base_size;
  p.level_roughness = level_roughness;
  return p;
}

TEST(PrefilterLevelRoughness, LinearIsGltfsLod) {
  const PrefilterParams p = schedule(LevelRoughness::Linear, 5);
  const double expected[] = {0, 0.25, 0.5, 0.75, 1};
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(p.roughness(i), expected[i]) << i;
}

TEST(PrefilterLevelRoughness, FilamentInvertsItsLod) {
  const PrefilterParams p = schedule(LevelRoughness::Filament, 5);
  // 1 - sqrt(1 - i / 4): i = 1 gives 1 - sqrt(3) / 2, i = 2 gives 1 - sqrt(1 / 2).
  EXPECT_DOUBLE_EQ(p.roughness(0), 0);
  EXPECT_NEAR(p.roughness(1), 0.1339745962155614, 1e-15);
  EXPECT_NEAR(p.roughness(2), 0.2928932188134524, 1e-15);
  EXPECT_DOUBLE_EQ(p.roughness(4), 1);
  for (int i = 0; i < 5; ++i) {
    const double r = p.roughness(i);
    EXPECT_NEAR(4 * r * (2 - r), i, 1e-12) << i;
  }
}

TEST(PrefilterLevelRoughness, BabylonDoublesAlphaEvery0Point8Levels) {
  const PrefilterParams p = schedule(LevelRoughness::Babylon, 8);
  EXPECT_DOUBLE_EQ(p.roughness(0), 0);
  // Level 1: alpha = 2^1.25 / 256 = 0.00929068..., r = sqrt(alpha).
  EXPECT_NEAR(p.roughness(1), 0.0963882, 1e-7);
  for (int i = 1; i < 8; ++i) {
    const double alpha = std::exp2(i / 0.8) / 256;
    EXPECT_NEAR(p.roughness(i), std::sqrt(alpha), 1e-15) << i;
  }
  EXPECT_NEAR(p.roughness(7), std::sqrt(std::exp2(8.75) / 256), 1e-15);  // alpha 1.68, as HDRFiltering has it
}

TEST(PrefilterLevelRoughness, EverySchedulesNameAndFormulaIsStated) {
  EXPECT_EQ(enum_names_joined<LevelRoughness>(), "linear, filament, babylon");
  for (const auto& e : enum_entries(LevelRoughness{}))
    EXPECT_NE(std::string(level_roughness_formula(e.value)).find("level i"), std::string::npos);
}

}  // namespace
}  // namespace lp

// The server's model cache on real files: a model is served from the cache while none of the files it
// was read from has changed, and loaded again once one has (the model file, its material library or a
// texture); its bytes are a cache entry of the memory budget; a preset's model is held in the budget once.
#include "server/assets/model_cache.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/textured_preset.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

constexpr std::array<uint8_t, 3> kRed{255, 0, 0}, kGreen{0, 255, 0};

// A textured quad in a folder of its own, and a cache on an unlimited budget.
class ModelCacheTest : public ::testing::Test {
 protected:
  ModelCacheTest() { test::write_textured_quad(dir_.path(), test::solid_png(2, 2, kRed)); }
  fs::path file(const char* name) const { return dir_.path() / name; }
  std::shared_ptr<const Model> get() { return cache_.get(file("quad.obj"), {}); }
  // Rewrites a file of the model as an edit does, a second after its last modification (so that the
  // edit shows in the modification time whatever the file system's time resolution).
  void edit(const char* name, const std::string& bytes) {
    const auto before = fs::last_write_time(file(name));
    std::ofstream(file(name), std::ios::binary) << bytes;
    fs::last_write_time(file(name), before + std::chrono::seconds(1));
  }
  static Rgb albedo_texel(const Model& m) {
    return m.materials.at(0).base_color->texture->texel(0, 0, 0).rgb();
  }

  test::TempDir dir_;
  MemoryBudget budget_;
  ModelCache cache_{budget_};
};

TEST_F(ModelCacheTest, AnUnchangedModelIsServedFromTheCacheAndCountedOnce) {
  const auto first = get();
  EXPECT_EQ(first->files.size(), 3u);  // quad.obj, quad.mtl, albedo.png
  EXPECT_EQ(get(), first);
  EXPECT_EQ(cache_.size(), 1u);
  EXPECT_EQ(budget_.used(MemoryUse::Cache), first->memory_bytes());
}

TEST_F(ModelCacheTest, AnEditedTextureIsLoadedAgain) {
  auto red = get();
  EXPECT_EQ(albedo_texel(*red), (Rgb{1, 0, 0}));
  edit("albedo.png", test::solid_png(2, 2, kGreen));
  const auto green = get();
  EXPECT_NE(green, red);
  EXPECT_EQ(albedo_texel(*green), (Rgb{0, 1, 0}));
  EXPECT_EQ(albedo_texel(*red), (Rgb{1, 0, 0}));  // a render holding the old model keeps it
  EXPECT_EQ(get(), green);
  EXPECT_EQ(cache_.size(), 1u);
  // The old model's bytes stay reserved while it is held, and return with it.
  EXPECT_EQ(budget_.used(MemoryUse::Cache), red->memory_bytes() + green->memory_bytes());
  red.reset();
  EXPECT_EQ(budget_.used(MemoryUse::Cache), green->memory_bytes());
}

TEST_F(ModelCacheTest, AnEditedMaterialLibraryIsLoadedAgain) {
  const auto white = get();
  EXPECT_EQ(white->materials.at(0).base_color_factor.r, 1.0f);
  edit("quad.mtl", "newmtl m\nKd 0.25 0.25 0.25\nmap_Kd albedo.png\n");
  const auto grey = get();
  EXPECT_NE(grey, white);
  EXPECT_EQ(grey->materials.at(0).base_color_factor.r, 0.25f);
}

TEST_F(ModelCacheTest, AModelWhoseTextureIsGoneIsAnErrorAndLeavesTheCache) {
  const auto model = get();
  fs::remove(file("albedo.png"));
  try {
    get();
    FAIL() << "a missing texture was not reported";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::NotFound);
    EXPECT_NE(std::string(e.what()).find("albedo.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(cache_.size(), 0u);
}

// A 512 x 512 texture takes 4 MiB with its mip levels.
TEST(ModelCacheBudget, AModelOverTheWholeBudgetIsRefusedNamingItAndReservesNothing) {
  test::TempDir dir;
  test::write_textured_quad(dir.path(), test::solid_png(512, 512, kRed));
  MemoryBudget budget(2 << 20);
  ModelCache cache(budget);
  try {
    cache.get(dir.path() / "quad.obj", {});
    FAIL() << "the model fit a 2 MiB budget";
  } catch (const MemoryBudgetError& e) {
    EXPECT_FALSE(e.transient());
    EXPECT_NE(std::string(e.what()).find("the model quad.obj"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget.used(), 0);
  EXPECT_EQ(cache.size(), 0u);
}

TEST(ModelCacheBudget, ALoadedModelKeepsOnlyItsOwnBytesAndRequestsAtOnceShareOneLoad) {
  test::TempDir dir;
  test::write_textured_quad(dir.path(), test::solid_png(512, 512, kRed));
  MemoryBudget budget(64 << 20);
  ModelCache cache(budget);
  std::vector<std::future<std::shared_ptr<const Model>>> models;
  for (int i = 0; i < 4; ++i)
    models.push_back(std::async(std::launch::async, [&] { return cache.get(dir.path() / "quad.obj", {}); }));
  const auto first = models[0].get();
  for (size_t i = 1; i < models.size(); ++i) EXPECT_EQ(models[i].get(), first);
  EXPECT_EQ(budget.used(MemoryUse::Cache), first->memory_bytes());
  EXPECT_EQ(budget.used(MemoryUse::Transient), 0);
}

TEST(ModelCacheBuiltin, APresetModelIsHeldInTheBudgetOnce) {
  const auto preset = render::textured_preset_model();
  MemoryBudget budget;
  ModelCache cache(budget);
  cache.hold_builtin(preset, "the textured preset's model");
  cache.hold_builtin(preset, "the textured preset's model");
  EXPECT_EQ(budget.used(MemoryUse::Held), preset->memory_bytes());
  // At least its textures' base levels, as float RGB: the bricks' colour and normal map, the checkerboard.
  const int64_t texels = 2 * render::kBrickTextureWidth * render::kBrickTextureHeight +
                         render::kCheckerTextureSize * render::kCheckerTextureSize;
  EXPECT_GT(preset->memory_bytes(), texels * 3 * int64_t(sizeof(float)));
}

TEST(ModelCacheBuiltin, APresetModelOverTheBudgetIsRefusedNamingIt) {
  const auto preset = render::textured_preset_model();
  MemoryBudget budget(preset->memory_bytes() - 1);
  ModelCache cache(budget);
  try {
    cache.hold_builtin(preset, "the textured preset's model");
    FAIL() << "the preset's model fit a budget a byte too small";
  } catch (const MemoryBudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("the textured preset's model"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget.used(), 0);
}

}  // namespace
}  // namespace lp::server

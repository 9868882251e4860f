// Babylon.js .env files: the bytes write_babylon_env lays out (magic, the manifest's fields as
// Babylon's GetEnvInfo reads them, NUL, images at their positions from the manifest's end), the round
// trip through read_babylon_env, and refusals.
#include "engine/image/babylon_env.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "engine/core/error.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

// A file of width 4: 3 levels of 6 faces, image k holding k + 1 bytes of value k.
BabylonEnv small_env() {
  BabylonEnv env;
  env.width = 4;
  for (size_t k = 0; k < babylon_env_images(4); ++k) env.specular.emplace_back(k + 1, uint8_t(k));
  BabylonSphericalPolynomial p;
  p.xx = {1, 2, 3};
  p.zx = {-0.5, 0.25, 0};
  env.irradiance = p;
  return env;
}

TEST(BabylonEnv, LevelsReachOneTexel) {
  EXPECT_EQ(babylon_env_levels(1), 1);
  EXPECT_EQ(babylon_env_levels(256), 9);
  EXPECT_EQ(babylon_env_images(256), 54u);
}

TEST(BabylonEnv, LaysOutMagicManifestAndImages) {
  const auto bytes = write_babylon_env(small_env());
  const std::vector<uint8_t> magic = {0x86, 0x16, 0x87, 0x96, 0xf6, 0xd6, 0x96, 0x36};
  ASSERT_TRUE(std::equal(magic.begin(), magic.end(), bytes.begin()));
  const auto nul = std::find(bytes.begin() + 8, bytes.end(), 0);
  ASSERT_NE(nul, bytes.end());
  const auto m = nlohmann::json::parse(bytes.begin() + 8, nul);
  EXPECT_EQ(m["version"], 2);
  EXPECT_EQ(m["width"], 4);
  EXPECT_EQ(m["imageType"], "image/png");
  EXPECT_EQ(m["specular"]["lodGenerationScale"], 0.8);
  EXPECT_EQ(m["irradiance"]["xx"], nlohmann::json::array({1.0, 2.0, 3.0}));
  EXPECT_EQ(m["irradiance"]["zx"][0], -0.5);
  const auto& mipmaps = m["specular"]["mipmaps"];
  ASSERT_EQ(mipmaps.size(), 18u);
  const size_t payload = size_t(nul - bytes.begin()) + 1;
  size_t position = 0;
  for (size_t k = 0; k < 18; ++k) {
    EXPECT_EQ(mipmaps[k]["position"], position);
    EXPECT_EQ(mipmaps[k]["length"], k + 1);
    EXPECT_EQ(bytes[payload + position], k);  // image k at its place
    position += k + 1;
  }
  EXPECT_EQ(bytes.size(), payload + position);
}

TEST(BabylonEnv, RoundTrips) {
  const BabylonEnv env = small_env();
  const BabylonEnv back = read_babylon_env(write_babylon_env(env));
  EXPECT_EQ(back.width, 4);
  EXPECT_EQ(back.image_type, "image/png");
  EXPECT_EQ(back.lod_generation_scale, 0.8);
  EXPECT_EQ(back.irradiance, env.irradiance);
  EXPECT_EQ(back.specular, env.specular);
}

TEST(BabylonEnv, RefusesWhatItCannotWrite) {
  BabylonEnv env = small_env();
  env.specular.pop_back();
  EXPECT_THROW(write_babylon_env(env), Error);
  env = small_env();
  env.width = 3;
  EXPECT_THROW(write_babylon_env(env), Error);
}

TEST(BabylonEnv, RefusesBrokenFiles) {
  const auto bytes = write_babylon_env(small_env());
  const auto kind = [](std::vector<uint8_t> b) {
    try {
      read_babylon_env(b);
    } catch (const Error& e) {
      return e.kind();
    }
    return ErrorKind::Internal;
  };
  EXPECT_EQ(kind({1, 2, 3}), ErrorKind::Unsupported);
  EXPECT_EQ(kind(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 40)), ErrorKind::Corrupt);  // no NUL
  EXPECT_EQ(kind(std::vector<uint8_t>(bytes.begin(), bytes.end() - 1)),
            ErrorKind::Corrupt);  // last image cut
  std::vector<uint8_t> other_version = bytes;
  const auto at =
      std::search(other_version.begin(), other_version.end(), "\"version\":2", "\"version\":2" + 11);
  ASSERT_NE(at, other_version.end());
  at[10] = '3';
  EXPECT_EQ(kind(other_version), ErrorKind::Corrupt);
  // Offsets, sizes and versions are whole numbers: 1e300 is refused, not converted.
  std::vector<uint8_t> huge = bytes;
  const std::string position = "\"position\":0";
  const auto p = std::search(huge.begin(), huge.end(), position.begin(), position.end());
  ASSERT_NE(p, huge.end());
  const std::string replaced = "\"position\":1e300";
  huge.erase(p, p + ptrdiff_t(position.size()));
  huge.insert(p, replaced.begin(), replaced.end());
  EXPECT_EQ(kind(huge), ErrorKind::Corrupt);
}

TEST(BabylonEnv, ReadsTheFuzzSeeds) {
  const auto bytes = [](const char* name) {
    const auto path = test::fuzz_corpus_path("babylon_env", name);
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
  };
  const BabylonEnv one = read_babylon_env(bytes("width_1.env"));
  EXPECT_EQ(one.width, 1);
  EXPECT_EQ(one.specular.size(), 6u);
  EXPECT_TRUE(one.irradiance);
  const BabylonEnv four = read_babylon_env(bytes("width_4_no_irradiance.env"));
  EXPECT_EQ(four.specular.size(), 18u);
  EXPECT_FALSE(four.irradiance);
}

}  // namespace
}  // namespace lp

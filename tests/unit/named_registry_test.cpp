// NamedRegistry, the registry of what clients name (maps, assets): a taken or held name is refused with
// 409, the maximum counts held names too (507), a released hold frees its name, and the refusals say what
// the registry holds as the API has always said it.
#include "server/storage/named_registry.hpp"

#include <gtest/gtest.h>

#include <string>

#include "api/api_error.hpp"
#include "server/assets/asset_registry.hpp"
#include "server/maps/envmap_registry.hpp"

namespace lp::server {
namespace {

api::ErrorCode code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const api::ApiError& e) {
    return e.code();
  }
  ADD_FAILURE() << "no ApiError";
  return api::ErrorCode::Internal;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const api::ApiError& e) {
    return e.what();
  }
  return "";
}

TEST(NamedRegistry, HoldsAddsFindsAndRemoves) {
  NamedRegistry<int> r(2, {"an int", "int", "named", "ints (2)"});
  auto hold = r.hold("a");
  EXPECT_EQ(r.find("a"), nullptr);  // held, not yet added
  EXPECT_EQ(code_of([&] { r.hold("a"); }), api::ErrorCode::Conflict);
  EXPECT_EQ(*hold->add(7), 7);
  EXPECT_EQ(*r.get("a"), 7);
  EXPECT_EQ(code_of([&] { r.add("a", 8); }), api::ErrorCode::Conflict);
  EXPECT_TRUE(r.remove("a"));
  EXPECT_FALSE(r.remove("a"));
  EXPECT_EQ(code_of([&] { r.get("a"); }), api::ErrorCode::NotFound);
}

TEST(NamedRegistry, HeldNamesCountAgainstTheMaximumUntilReleased) {
  NamedRegistry<int> r(2, {"an int", "int", "named", "ints (2)"});
  r.add("a", 1);
  {
    auto hold = r.hold("b");
    EXPECT_EQ(code_of([&] { r.hold("c"); }), api::ErrorCode::InsufficientStorage);
  }  // released without an entry
  EXPECT_EQ(r.find("b"), nullptr);
  r.add("c", 3);
  ASSERT_EQ(r.list().size(), 2u);
  EXPECT_EQ(*r.list()[0], 1);  // by name
  EXPECT_EQ(*r.list()[1], 3);
}

TEST(NamedRegistry, TheMapAndAssetRegistriesSayWhatTheyHold) {
  EnvMapRegistry maps(1);
  maps.add("sky", "exr", "upload", nullptr);
  EXPECT_EQ(message_of([&] { maps.add("sky", "exr", "upload", nullptr); }),
            "an environment map named 'sky' exists");
  EXPECT_EQ(message_of([&] { maps.add("sea", "exr", "upload", nullptr); }),
            "the server holds the maximum number of maps (1); delete one first");
  EXPECT_EQ(message_of([&] { maps.get("sun"); }), "no environment map with id 'sun'");
  AssetRegistry assets(1);
  EXPECT_EQ(code_of([&] { assets.hold("../x"); }), api::ErrorCode::InvalidField);
  auto hold = assets.hold("chair");
  EXPECT_EQ(message_of([&] { assets.hold("chair"); }), "an asset named 'chair' exists");
  EXPECT_EQ(message_of([&] { assets.hold("table"); }),
            "the server holds the maximum number of assets (--max-assets 1); delete one first");
  EXPECT_EQ(message_of([&] { assets.get("lamp"); }), "no asset named 'lamp'");
}

}  // namespace
}  // namespace lp::server

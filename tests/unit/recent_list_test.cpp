// RecentList, the bounded most-recently-used list the scale-out caches keep (maps, mesh bundles, fetched
// bundles): a use moves an entry to the front, an addition past the capacity drops the least recently
// used, and an addition under a kept key replaces its value.
#include "server/scale_out/recent_list.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lp::server {
namespace {

TEST(RecentList, DropsTheLeastRecentlyUsedPastItsCapacity) {
  RecentList<std::string, int> list(2);
  EXPECT_TRUE(list.add("a", 1).empty());
  EXPECT_TRUE(list.add("b", 2).empty());
  ASSERT_NE(list.use("a"), nullptr);  // b is now the least recently used
  const auto dropped = list.add("c", 3);
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].first, "b");
  EXPECT_EQ(dropped[0].second, 2);
  EXPECT_EQ(list.use("b"), nullptr);
  ASSERT_NE(list.use("a"), nullptr);
  EXPECT_EQ(*list.use("a"), 1);
  EXPECT_EQ(*list.use("c"), 3);
}

TEST(RecentList, AnAdditionUnderAKeptKeyReplacesItsValue) {
  RecentList<std::string, int> list(2);
  list.add("a", 1);
  list.add("b", 2);
  EXPECT_TRUE(list.add("a", 10).empty());  // still two entries: nothing dropped
  EXPECT_EQ(*list.use("a"), 10);
  EXPECT_EQ(*list.use("b"), 2);
}

TEST(RecentList, FindLeavesTheOrderAlone) {
  RecentList<std::string, int> list(2);
  list.add("a", 1);
  list.add("b", 2);
  const int* found = list.find_if([](int v) { return v == 1; });
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(*found, 1);
  EXPECT_EQ(list.find_if([](int v) { return v == 7; }), nullptr);
  const auto dropped = list.add("c", 3);  // a was not used by the find: it goes first
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].first, "a");
}

TEST(RecentList, KeysAloneForASetOfRecentNames) {
  RecentList<std::string> list(1);
  list.add("x", {});
  EXPECT_NE(list.use("x"), nullptr);
  const auto dropped = list.add("y", {});
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].first, "x");
}

}  // namespace
}  // namespace lp::server

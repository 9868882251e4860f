// Error messages quote client input in bounded excerpts.
#include "api/excerpt.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lp::api {
namespace {

TEST(Excerpt, ShortTextIsKeptWhole) {
  EXPECT_EQ(excerpt("abc"), "abc");
}

TEST(Excerpt, LongTextIsCutAndMarked) {
  const std::string cut = excerpt(std::string(10'000, 'x'));
  EXPECT_EQ(cut, std::string(kExcerptBytes, 'x') + "...");
}

TEST(Excerpt, CutsOnAUtf8Boundary) {
  std::string text(kExcerptBytes - 1, 'a');
  text += "\xC3\xA9\xC3\xA9";  // a two-byte character straddles the limit
  EXPECT_EQ(excerpt(text), std::string(kExcerptBytes - 1, 'a') + "...");
}

TEST(Describe, ContainersBySizeScalarsAsJson) {
  EXPECT_EQ(describe(nlohmann::json::array({1, 2, 3})), "an array of 3 items");
  EXPECT_EQ(describe(nlohmann::json{{"a", 1}}), "an object with 1 members");
  EXPECT_EQ(describe(nlohmann::json(2.5)), "2.5");
  EXPECT_EQ(describe(nlohmann::json("hi")), "\"hi\"");
  EXPECT_EQ(describe(nlohmann::json(std::string(500, 'y'))),
            "\"" + std::string(kExcerptBytes, 'y') + "...\"");
}

}  // namespace
}  // namespace lp::api

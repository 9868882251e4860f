// Client input quoted in error messages is bounded: long text is cut on a character boundary, arrays and
// objects are described by their size.
#include "api/excerpt.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lp::api {
namespace {

TEST(Excerpt, ShortTextIsKeptWhole) {
  EXPECT_EQ(excerpt(""), "");
  EXPECT_EQ(excerpt("gold"), "gold");
  EXPECT_EQ(excerpt(std::string(kExcerptBytes, 'x')), std::string(kExcerptBytes, 'x'));
}

TEST(Excerpt, LongTextIsCutAndMarked) {
  EXPECT_EQ(excerpt(std::string(kExcerptBytes + 1, 'x')), std::string(kExcerptBytes, 'x') + "...");
  EXPECT_EQ(excerpt(std::string(200'000, 'x')), std::string(kExcerptBytes, 'x') + "...");
}

TEST(Excerpt, NeverCutsAUtf8Character) {
  std::string text(kExcerptBytes - 1, 'a');
  text += "\xC3\xA9\xC3\xA9";  // two-byte characters; the first straddles the cut
  EXPECT_EQ(excerpt(text), std::string(kExcerptBytes - 1, 'a') + "...");
  std::string euros;
  while (euros.size() < 2 * kExcerptBytes) euros += "\xE2\x82\xAC";  // three-byte characters
  const std::string cut = excerpt(euros);
  EXPECT_EQ(cut.size(), kExcerptBytes / 3 * 3 + 3);
  EXPECT_EQ(cut.substr(0, 3), "\xE2\x82\xAC");
  EXPECT_EQ(cut.substr(cut.size() - 6), "\xE2\x82\xAC...");
}

TEST(Describe, ScalarsAsJsonContainersBySize) {
  EXPECT_EQ(describe(nlohmann::json(2.5)), "2.5");
  EXPECT_EQ(describe(nlohmann::json(-7)), "-7");
  EXPECT_EQ(describe(nlohmann::json(true)), "true");
  EXPECT_EQ(describe(nlohmann::json(nullptr)), "null");
  EXPECT_EQ(describe(nlohmann::json("hi")), "\"hi\"");
  EXPECT_EQ(describe(nlohmann::json(std::string(500, 'y'))),
            "\"" + std::string(kExcerptBytes, 'y') + "...\"");
  EXPECT_EQ(describe(nlohmann::json::array({1, 2, 3})), "an array of 3 items");
  EXPECT_EQ(describe(nlohmann::json::array({nlohmann::json::array()})), "an array of 1 item");
  EXPECT_EQ(describe(nlohmann::json::object({{"a", 1}, {"b", 2}})), "an object with 2 members");
  EXPECT_EQ(describe(nlohmann::json::object({{"a", 1}})), "an object with 1 member");
}

}  // namespace
}  // namespace lp::api

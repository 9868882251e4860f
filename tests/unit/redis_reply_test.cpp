// parse_reply (server/scale_out/redis_client.hpp): the Redis protocol's replies read as a connection reads
// them, and arrays over kMaxRedisArrayElements refused before anything is allocated for them (a count the
// bytes cannot hold is no whole reply either).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "server/scale_out/redis_client.hpp"
#include "support/test_data.hpp"

namespace lp::server {
namespace {

TEST(RedisReply, ReadsNestedArraysStringsAndIntegers) {
  const auto r = parse_reply("*3\r\n$5\r\nhello\r\n:42\r\n*1\r\n+OK\r\n");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->type, RedisReply::Type::Array);
  ASSERT_EQ(r->elements.size(), 3u);
  EXPECT_EQ(r->elements[0].text, "hello");
  EXPECT_EQ(r->elements[1].integer, 42);
  ASSERT_EQ(r->elements[2].elements.size(), 1u);
  EXPECT_EQ(r->elements[2].elements[0].text, "OK");
}

TEST(RedisReply, ABulkStringThatLooksLikeAnArrayHeaderIsData) {
  const auto r = parse_reply("$11\r\n*99999999\r\n\r\n");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->text, "*99999999\r\n");
}

TEST(RedisReply, AnArrayCountTheBytesCannotHoldIsRefused) {
  EXPECT_FALSE(parse_reply("*344444444\r\n"));
  EXPECT_FALSE(parse_reply("*2\r\n:1\r\n"));  // one element short: no whole reply
  EXPECT_TRUE(parse_reply("*-1\r\n"));        // a null array
  // The fuzzer's reproducer: a count of 344444444 under nested headers (hiredis would calloc 2.7 GB).
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("redis_reply", "huge_array_count"));
  EXPECT_FALSE(parse_reply({reinterpret_cast<const char*>(bytes.data()), bytes.size()}));
}

// `count` empty status replies under one array header.
std::string array_of(int count) {
  std::string wire = fmt::format("*{}\r\n", count);
  for (int i = 0; i < count; ++i) wire += "+\r\n";
  return wire;
}

TEST(RedisReply, AnArrayOverTheBoundIsRefusedAsOnAConnection) {
  const auto whole = parse_reply(array_of(kMaxRedisArrayElements));
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->elements.size(), size_t(kMaxRedisArrayElements));
  EXPECT_FALSE(parse_reply(array_of(kMaxRedisArrayElements + 1)));
  EXPECT_FALSE(parse_reply("*1\r\n" + array_of(kMaxRedisArrayElements + 1)));
}

}  // namespace
}  // namespace lp::server

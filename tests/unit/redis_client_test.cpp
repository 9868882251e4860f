// RedisClient (server/redis_client.hpp) against a real redis-server on loopback.
#include "server/redis_client.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "support/redis_process.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;

// Appends entries {first: i, end: i + 1} for i in [0, count) to the stream, inside Redis.
void add_entries(RedisClient& client, std::string_view stream, int count) {
  client.command(
      {"EVAL",
       "for i = 0, tonumber(ARGV[1]) - 1 do redis.call('XADD', KEYS[1], '*', 'first', i, 'end', i + 1) end",
       "1", stream, std::to_string(count)});
}

TEST(RedisClient, ReadsAStreamOfManyPagesWholeAndInOrder) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis;
  RedisClient client(parse_redis_url(redis.url()), 5s);
  constexpr int kEntries = 150'000;  // pages of 65536: two whole ones and a part
  add_entries(client, "items", kEntries);
  const auto entries = client.xrange("items");
  ASSERT_EQ(entries.size(), size_t(kEntries));
  int out_of_place = 0;
  for (size_t i = 0; i < entries.size(); ++i)
    if (entries[i].field("first") != std::to_string(i) || entries[i].stream != "items") ++out_of_place;
  EXPECT_EQ(out_of_place, 0);
  EXPECT_TRUE(client.xrange("absent").empty());
}

}  // namespace
}  // namespace lp::server

// RedisClient (server/scale_out/redis_client.hpp) against a real redis-server on loopback, and against a
// stand-in for a broken or hostile Redis that answers with an array header of 344444444 elements (2.7 GB of
// element pointers, were the table allocated).
#include "server/scale_out/redis_client.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

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

// An external Redis as a broken one could be: listens on a loopback port and answers whatever arrives
// on its n-th connection with answers[n] (the last one for later connections), one connection at a time.
class FakeRedis {
 public:
  explicit FakeRedis(std::vector<std::string> answers)
      : answers_(std::move(answers)), listener_(socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (listener_ < 0 || bind(listener_, reinterpret_cast<sockaddr*>(&addr), len) != 0 ||
        listen(listener_, 4) != 0 || getsockname(listener_, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
      throw std::runtime_error("cannot listen on loopback");
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeRedis() {
    shutdown(listener_, SHUT_RDWR);  // ends a waiting accept(); the client closes its connection first
    thread_.join();
    close(listener_);
  }
  FakeRedis(const FakeRedis&) = delete;
  FakeRedis& operator=(const FakeRedis&) = delete;

  int port() const { return port_; }
  int answered() const { return answered_; }  // commands answered, over all connections

 private:
  void serve() {
    for (size_t n = 0;; ++n) {
      const int fd = accept(listener_, nullptr, nullptr);
      if (fd < 0) return;
      const std::string& answer = answers_[std::min(n, answers_.size() - 1)];
      char command[4096];
      while (read(fd, command, sizeof command) > 0) {
        ++answered_;  // before the client can have the answer
        if (write(fd, answer.data(), answer.size()) < 0) break;
      }
      close(fd);
    }
  }

  const std::vector<std::string> answers_;
  const int listener_;
  int port_ = 0;
  std::atomic<int> answered_{0};
  std::thread thread_;
};

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

TEST(RedisClient, ReadsTheMembersOfASet) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis;
  RedisClient client(parse_redis_url(redis.url()), 5s);
  for (const char* id : {"r1", "r2", "r3"}) client.sadd("renders", id);
  auto members = client.smembers("renders");
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<std::string>{"r1", "r2", "r3"}));
}

// Refused before hiredis allocates the table, at once (not sent again until retry_for runs out: the
// same server would answer the same), naming the count, the bound and the server; the connection is
// dropped and the next command opens another.
TEST(RedisClient, AnArrayOverTheBoundIsRefusedAtOnceNamingIt) {
  FakeRedis fake({"*344444444\r\n", "*2\r\n$2\r\nr1\r\n$2\r\nr2\r\n"});
  RedisClient client(parse_redis_url("redis://127.0.0.1:" + std::to_string(fake.port())), 10s);
  std::string message;
  try {
    client.smembers("renders");
  } catch (const RedisError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "redis SMEMBERS: redis://127.0.0.1:" + std::to_string(fake.port()) +
                         " answered an array of 344444444 elements, over the bound of " +
                         std::to_string(kMaxRedisArrayElements) + "; connection dropped");
  EXPECT_EQ(fake.answered(), 1);
  EXPECT_EQ(client.smembers("renders"), (std::vector<std::string>{"r1", "r2"}));
}

TEST(RedisClient, ANestedArrayOverTheBoundIsRefusedToo) {
  FakeRedis fake({"*2\r\n:1\r\n*1048577\r\n"});
  RedisClient client(parse_redis_url("redis://127.0.0.1:" + std::to_string(fake.port())), 10s);
  try {
    client.command({"XINFO", "GROUPS", "items"});
    ADD_FAILURE() << "no RedisError";
  } catch (const RedisError& e) {
    EXPECT_NE(std::string(e.what()).find("an array of 1048577 elements"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lp::server

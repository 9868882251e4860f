// parse_redis_url and complete_redis (server/scale_out/redis_url.hpp, scale_out_config.hpp): the forms
// --redis takes, the password from the URL, a file or LIGHTPROBE_REDIS_PASSWORD, and that no URL shown
// and no message holds the password.
#include "server/scale_out/redis_url.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "server/scale_out/scale_out_config.hpp"
#include "support/temp_dir.hpp"

namespace lp::server {
namespace {

// The message parse_redis_url throws for `url`; empty if it parses.
std::string refusal(const std::string& url) {
  try {
    parse_redis_url(url);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RedisUrl, TakesHostPortAndDatabase) {
  const RedisAddress a = parse_redis_url("redis://cache.internal:6380/3");
  EXPECT_EQ(a.host, "cache.internal");
  EXPECT_EQ(a.port, 6380);
  EXPECT_EQ(a.db, 3);
  EXPECT_FALSE(a.tls);
  EXPECT_EQ(a.user, "");
  EXPECT_FALSE(a.password);
  const RedisAddress b = parse_redis_url("redis://redis");
  EXPECT_EQ(b.port, kRedisDefaultPort);
  EXPECT_EQ(b.db, 0);
  EXPECT_EQ(parse_redis_url("redis://redis/").db, 0);
}

TEST(RedisUrl, RedissIsTls) {
  const RedisAddress a = parse_redis_url("rediss://redis.example.com:6390");
  EXPECT_TRUE(a.tls);
  EXPECT_EQ(a.url(), "rediss://redis.example.com:6390");
}

TEST(RedisUrl, TakesIpv6HostsInBrackets) {
  const RedisAddress a = parse_redis_url("redis://[::1]:7000/2");
  EXPECT_EQ(a.host, "::1");
  EXPECT_EQ(a.port, 7000);
  EXPECT_EQ(a.url(), "redis://[::1]:7000/2");
  EXPECT_EQ(parse_redis_url("rediss://u:p@[2001:db8::5]").host, "2001:db8::5");
}

TEST(RedisUrl, PercentDecodesUserAndPassword) {
  const RedisAddress a = parse_redis_url("redis://render%20farm:p%40ss%3Aw%2Fo%25rd@10.0.0.7:6379/1");
  EXPECT_EQ(a.user, "render farm");
  EXPECT_EQ(a.password, "p@ss:w/o%rd");
  const RedisAddress b = parse_redis_url("redis://:s3cret@localhost");
  EXPECT_EQ(b.user, "");
  EXPECT_EQ(b.password, "s3cret");
  const RedisAddress c = parse_redis_url("redis://worker@localhost");  // its password from elsewhere
  EXPECT_EQ(c.user, "worker");
  EXPECT_FALSE(c.password);
}

TEST(RedisUrl, TheUrlShownNeverHoldsThePassword) {
  EXPECT_EQ(parse_redis_url("redis://render%20farm:hunter2@10.0.0.7:6379/1").url(),
            "redis://render%20farm:***@10.0.0.7:6379/1");
  EXPECT_EQ(parse_redis_url("rediss://:hunter2@h").url(), "rediss://:***@h:6379");
  const std::string message = refusal("redis://user:hunter2@host:99999");
  EXPECT_NE(message, "");
  EXPECT_EQ(message.find("hunter2"), std::string::npos) << message;
  EXPECT_NE(message.find("redis://***@host:99999"), std::string::npos) << message;
  EXPECT_EQ(redacted_url("redis://a:b@c@d/1"), "redis://***@d/1");
  EXPECT_EQ(redacted_url("redis://host:1"), "redis://host:1");
}

TEST(RedisUrl, RefusesOtherForms) {
  for (const char* url : {"",
                          "http://host:6379",
                          "redis:/host",
                          "redis://",
                          "redis://:6379",
                          "redis://host:",
                          "redis://host:0",
                          "redis://host:65536",
                          "redis://host:-1",
                          "redis://host:12ab",
                          "redis://host/db",
                          "redis://host/-1",
                          "redis://host/1/2",
                          "redis://host/2000000",
                          "redis://host?db=1",
                          "redis://ho st",
                          "redis://[::1",
                          "redis://[::1]x",
                          "redis://[::1]:",
                          "redis://[nothex]",
                          "redis://u:p%4@host",
                          "redis://u:p%zz@host",
                          "redis://:@host",
                          "redis://@host",
                          "redis://u:@host",
                          "REDIS://host"}) {
    const std::string message = refusal(url);
    EXPECT_NE(message.find("redis://[USER:PASSWORD@]HOST[:PORT][/DB]"), std::string::npos) << url;
  }
  EXPECT_NE(refusal("redis://h/" + std::string(2000, '1')), "");
}

TEST(RedisPassword, ComesFromOneOfTheUrlAFileOrTheVariable) {
  test::TempDir dir;
  const auto file = dir.path() / "password";
  std::ofstream(file) << "from file\n";
  ScaleOutConfig from_file;
  from_file.redis = parse_redis_url("redis://worker@h");
  from_file.redis_password_file = file.string();
  complete_redis(from_file, std::nullopt);
  EXPECT_EQ(from_file.redis->password, "from file");
  EXPECT_EQ(from_file.redis->user, "worker");

  ScaleOutConfig from_variable;
  from_variable.redis = parse_redis_url("redis://h");
  complete_redis(from_variable, "from variable");
  EXPECT_EQ(from_variable.redis->password, "from variable");

  ScaleOutConfig twice;
  twice.redis = parse_redis_url("redis://:in-url@h");
  try {
    complete_redis(twice, "from variable");
    ADD_FAILURE() << "a password given twice was taken";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("comes from one of"), std::string::npos) << message;
    EXPECT_EQ(message.find("in-url"), std::string::npos) << message;
    EXPECT_EQ(message.find("from variable"), std::string::npos) << message;
  }
}

TEST(RedisPassword, RefusesWhatCannotBeUsed) {
  const auto refused = [](ScaleOutConfig c, std::optional<std::string> variable, const std::string& why) {
    try {
      complete_redis(c, variable);
      ADD_FAILURE() << "taken: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  ScaleOutConfig none;
  refused(none, "pw", "LIGHTPROBE_REDIS_PASSWORD needs --redis");
  ScaleOutConfig missing_file;
  missing_file.redis = parse_redis_url("redis://h");
  missing_file.redis_password_file = "/nonexistent/password";
  refused(missing_file, std::nullopt, "--redis-password-file: cannot read /nonexistent/password");
  ScaleOutConfig plain_with_ca;
  plain_with_ca.redis = parse_redis_url("redis://h");
  plain_with_ca.redis_tls.ca = "/etc/hostname";
  refused(plain_with_ca, std::nullopt, "--redis-tls-ca needs a rediss:// URL");
  ScaleOutConfig cert_without_key;
  cert_without_key.redis = parse_redis_url("rediss://h");
  cert_without_key.redis_tls.cert = "/etc/hostname";
  refused(cert_without_key, std::nullopt, "go together");
  ScaleOutConfig user_without_password;
  user_without_password.redis = parse_redis_url("redis://worker@h");
  refused(user_without_password, std::nullopt, "names the user worker but no password");
}

}  // namespace
}  // namespace lp::server

// The URLs --health-check accepts: http://HOST[:PORT][/PATH], IPv6 addresses in brackets, port 80 and
// path "/" when absent; anything else is refused with a message naming the URL.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "server/health_check.hpp"

namespace lp::server {
namespace {

TEST(HealthCheckUrl, Parts) {
  const auto v4 = parse_health_check_url("http://127.0.0.1:8080/api/v1/health");
  EXPECT_EQ(v4.host, "127.0.0.1");
  EXPECT_EQ(v4.port, 8080);
  EXPECT_EQ(v4.path, "/api/v1/health");
  const auto v6 = parse_health_check_url("http://[::1]:9000?x=1");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 9000);
  EXPECT_EQ(v6.path, "/?x=1");
  const auto bare = parse_health_check_url("http://localhost");
  EXPECT_EQ(bare.host, "localhost");
  EXPECT_EQ(bare.port, 80);
  EXPECT_EQ(bare.path, "/");
}

TEST(HealthCheckUrl, RefusesWhatItCannotUse) {
  for (const std::string url : {"", "https://127.0.0.1/", "127.0.0.1:8080/", "http://", "http:///health",
                                "http://host:0/", "http://host:65536/", "http://host:port/",
                                "http://user@host/", "http://[::1/", "http://host/#frag"}) {
    try {
      parse_health_check_url(url);
      ADD_FAILURE() << "accepted '" << url << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'" + url + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace lp::server

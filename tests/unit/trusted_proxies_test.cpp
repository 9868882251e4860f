// --trusted-proxy: the networks it names, and the client a request through them comes from (the
// right-most X-Forwarded-For hop that is not itself a trusted proxy).
#include "server/http/trusted_proxies.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace lp::server {
namespace {

TEST(TrustedProxies, NetworksOfBothFamilies) {
  TrustedProxies t;
  EXPECT_TRUE(t.empty());
  t.add("10.1.0.0/16");
  t.add("127.0.0.1");
  t.add("fd00::/8");
  EXPECT_FALSE(t.empty());
  EXPECT_TRUE(t.contains("10.1.255.3"));
  EXPECT_FALSE(t.contains("10.2.0.1"));
  EXPECT_TRUE(t.contains("127.0.0.1"));
  EXPECT_FALSE(t.contains("127.0.0.2"));
  EXPECT_TRUE(t.contains("::ffff:10.1.0.9"));  // an IPv4 peer of a dual-stack socket
  EXPECT_TRUE(t.contains("fd12:3456::1"));
  EXPECT_FALSE(t.contains("fe80::1"));
  EXPECT_FALSE(t.contains("not an address"));
}

TEST(TrustedProxies, ZeroBitsTrustsEveryAddressOfTheFamily) {
  TrustedProxies t;
  t.add("0.0.0.0/0");
  EXPECT_TRUE(t.contains("203.0.113.9"));
  EXPECT_FALSE(t.contains("2001:db8::1"));
}

TEST(TrustedProxies, TheClientIsTheRightMostUntrustedHop) {
  TrustedProxies t;
  t.add("127.0.0.1");
  t.add("10.0.0.0/8");
  // An untrusted peer is the client, whatever it claims.
  EXPECT_EQ(t.client_of("198.51.100.4", "203.0.113.7"), "198.51.100.4");
  EXPECT_EQ(t.client_of("127.0.0.1", "203.0.113.7"), "203.0.113.7");
  // Hops left of the first untrusted one were written by the client.
  EXPECT_EQ(t.client_of("127.0.0.1", "1.2.3.4, 203.0.113.7, 10.0.0.5"), "203.0.113.7");
  EXPECT_EQ(t.client_of("127.0.0.1", " 2001:db8::7 "), "2001:db8::7");
  // No header, only trusted hops, or a hop that is no address: the proxy itself.
  EXPECT_EQ(t.client_of("127.0.0.1", ""), "127.0.0.1");
  EXPECT_EQ(t.client_of("127.0.0.1", "10.0.0.5, 10.0.0.6"), "127.0.0.1");
  EXPECT_EQ(t.client_of("127.0.0.1", "203.0.113.7, unknown"), "127.0.0.1");
}

TEST(TrustedProxies, RefusesWhatIsNoNetwork) {
  for (const std::string bad : {"", "localhost", "10.0.0.0/33", "::/129", "10.0.0.0/", "10.0.0.0/x",
                                "10.0.0.0/-1", "10.0.0.0/8/8", "1.2.3"}) {
    TrustedProxies t;
    try {
      t.add(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--trusted-proxy"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("'" + bad + "'"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace lp::server

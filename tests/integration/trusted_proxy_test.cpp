// --trusted-proxy on the real server: a reverse proxy's connections are not limited per client, the
// requests it forwards are, by the client its X-Forwarded-For names; the access log names that client.
// Without the flag the header is ignored.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/raw_connection.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using json = nlohmann::json;
using test::RawConnection;
using test::RawResponse;

std::string forwarded(const std::string& chain) {
  return "X-Forwarded-For: " + chain + "\r\n";
}

// A request of `client` through the proxy that stays in flight: its body has not arrived.
std::unique_ptr<RawConnection> held_request(int port, const std::string& client) {
  auto c = std::make_unique<RawConnection>(port);
  c->send("POST /api/v1/renders HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
          "\r\nContent-Type: application/json\r\nContent-Length: 2\r\n" + forwarded(client) + "\r\n");
  return c;
}

RawResponse health_of(int port, const std::string& client) {
  RawConnection c(port);
  c.send(test::get_request(port, "/api/v1/health", forwarded(client)));
  return c.read_response();
}

TEST(TrustedProxy, ItsConnectionsAreNotLimitedPerClientItsClientsAre) {
  test::ServerProcess server({"--trusted-proxy", "127.0.0.1", "--max-connections-per-client", "2"});
  const int port = server.port();
  // Five connections from the proxy's one address, each answered.
  std::vector<std::unique_ptr<RawConnection>> pooled;
  for (int i = 0; i < 5; ++i) {
    pooled.push_back(std::make_unique<RawConnection>(port));
    pooled.back()->send(test::get_request(port, "/api/v1/health"));
    EXPECT_EQ(pooled.back()->read_response().status, 200) << "pooled connection " << i;
  }
  // One client holds its two requests; a third is refused, another client is answered.
  auto first = held_request(port, "198.51.100.9, 203.0.113.7");
  auto second = held_request(port, "203.0.113.7");
  RawResponse refused;  // once the server has read both heads
  for (int i = 0; i < 300 && refused.status != 503;
       ++i, std::this_thread::sleep_for(std::chrono::milliseconds(10)))
    refused = health_of(port, "203.0.113.7");
  EXPECT_EQ(refused.status, 503);
  const std::string message = json::parse(refused.body)["error"]["message"];
  EXPECT_NE(message.find("203.0.113.7"), std::string::npos) << message;
  EXPECT_NE(message.find("--max-connections-per-client"), std::string::npos) << message;
  EXPECT_EQ(health_of(port, "203.0.113.8").status, 200);
  // A client cannot pass for another by writing hops left of its own.
  EXPECT_EQ(health_of(port, "203.0.113.8, 203.0.113.7").status, 503);

  first->send("{}");  // answered: the client has a place again, once the server has counted the answer
  EXPECT_NE(first->read_response().status, 0);
  int status = 0;
  for (int i = 0; i < 100 && status != 200; ++i, std::this_thread::sleep_for(std::chrono::milliseconds(10)))
    status = health_of(port, "203.0.113.7").status;
  EXPECT_EQ(status, 200);
  second->send("{}");
  EXPECT_NE(second->read_response().status, 0);
}

TEST(TrustedProxy, TheAccessLogNamesTheForwardedClient) {
  test::ServerProcess server(
      {"--trusted-proxy", "127.0.0.0/8", "--log-format", "json", "--access-log-sample", "1"});
  EXPECT_EQ(health_of(server.port(), "192.0.2.1, 203.0.113.7").status, 200);
  EXPECT_TRUE(server.wait_log(R"("client":"203.0.113.7")")) << server.log();
}

TEST(TrustedProxy, WithoutTheFlagTheHeaderIsIgnored) {
  test::ServerProcess server(
      {"--max-connections-per-client", "2", "--log-format", "json", "--access-log-sample", "1"});
  const int port = server.port();
  EXPECT_EQ(health_of(port, "203.0.113.7").status, 200);
  EXPECT_TRUE(server.wait_log(R"("client":"127.0.0.1")")) << server.log();
  EXPECT_EQ(server.log().find("203.0.113.7"), std::string::npos);
  // Loopback connections count against the per-client limit, whatever they forward: two held (each
  // answered once, so the server has admitted it), a third refused. A held one is tried again while the
  // server has yet to count the closing of the connection before it.
  std::vector<std::unique_ptr<RawConnection>> held;
  for (const char* client : {"203.0.113.1", "203.0.113.2"}) {
    int status = 0;
    for (int i = 0; i < 100 && status != 200; ++i) {
      if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      auto c = std::make_unique<RawConnection>(port);
      c->send(test::get_request(port, "/api/v1/health", forwarded(client)));
      status = c->read_response().status;
      if (status == 200) held.push_back(std::move(c));
    }
    EXPECT_EQ(status, 200);
  }
  EXPECT_EQ(health_of(port, "203.0.113.3").status, 503);
}

}  // namespace
}  // namespace lp

// The HTTP transport of the real server under clients an HTTP library would not be: many idle, slow or
// streaming connections, pipelined requests, malformed or oversized heads and bodies, a second server on
// the same port, and more connections than the limits allow.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/http_reply.hpp"
#include "support/raw_connection.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using namespace std::chrono_literals;
using json = nlohmann::json;
using test::RawConnection;
using test::RawResponse;

std::string error_code(const RawResponse& r) {
  return json::parse(r.body)["error"]["code"];
}

RawResponse round_trip(int port, const std::string& request) {
  RawConnection c(port);
  c.send(request);
  return c.read_response();
}

std::string start_long_render(const test::ServerProcess& server) {
  const json body = {{"envmap", "default"},
                     {"scene", {{"preset", "sphere"}}},
                     {"width", 256},
                     {"height", 256},
                     {"spp", 65536}};
  const auto r = test::reply(server.client()->Post("/api/v1/renders", body.dump(), "application/json"));
  EXPECT_EQ(r.status, 202) << r.body;
  return r.body_json()["id"];
}

long resident_kib(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

TEST(Transport, HealthAnswersWithin100msWhileIdleSlowAndStreamConnectionsAreOpen) {
  constexpr int kIdle = 256, kSlow = 64, kStreams = 8;  // kStreams: the --max-event-streams default
  // Long timeouts, so that every connection below is still open when health is timed.
  test::ServerProcess server({"--keep-alive-timeout-s", "300", "--header-timeout-s", "300"});
  const int port = server.port();
  const std::string id = start_long_render(server);

  std::vector<std::unique_ptr<RawConnection>> streams, slow, idle;
  for (int i = 0; i < kStreams; ++i) {
    streams.push_back(std::make_unique<RawConnection>(port));
    streams.back()->send(test::get_request(port, "/api/v1/renders/" + id + "/events"));
    ASSERT_TRUE(streams.back()->read_until("data: ")) << "stream " << i;
  }
  for (int i = 0; i < kSlow; ++i) {  // slowloris: a head that never ends
    slow.push_back(std::make_unique<RawConnection>(port));
    slow.back()->send("GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ");
  }
  for (int i = 0; i < kIdle; ++i) {  // keep-alive connections left idle after one request
    idle.push_back(std::make_unique<RawConnection>(port));
    idle.back()->send(test::get_request(port, "/api/v1/health"));
    ASSERT_EQ(idle.back()->read_response().status, 200) << "idle " << i;
  }
  for (auto& s : slow) s->send("1\r\nX-Slower: ");

  for (int i = 0; i < 10; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const RawResponse r =
        round_trip(port, test::get_request(port, "/api/v1/health", "Connection: close\r\n"));
    const auto elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_EQ(r.status, 200);
    EXPECT_LT(elapsed, 100ms) << "health request " << i << " took "
                              << std::chrono::duration<double, std::milli>(elapsed).count() << " ms";
  }
  // They were all still open: idle ones answer again, slow ones got no answer, streams still stream.
  for (int i = 0; i < kIdle; i += 51) {
    idle[size_t(i)]->send(test::get_request(port, "/api/v1/health"));
    EXPECT_EQ(idle[size_t(i)]->read_response().status, 200);
  }
  for (auto& s : slow) EXPECT_TRUE(s->received().empty());
  EXPECT_TRUE(streams.front()->read_until("event: progress"));
}

TEST(Transport, ASecondServerOnAServedPortFailsToBind) {
  test::ServerProcess first;
  test::TempDir state;
  const auto second = test::run_until_exit(
      {"--port", std::to_string(first.port()), "--state-dir", state.path().string()}, 10s);
  EXPECT_NE(second.exit_status, 0) << second.output;
  EXPECT_NE(second.output.find("Address already in use"), std::string::npos) << second.output;
  EXPECT_EQ(test::reply(first.client()->Get("/api/v1/health")).status, 200);
}

TEST(Transport, PipelinedRequestsGetTheirAnswersInOrder) {
  const int port = test::shared_server().port();
  RawConnection c(port);
  ASSERT_TRUE(c.send(test::get_request(port, "/api/v1/health") +
                     test::post_request(port, "/api/v1/renders", "{}") +
                     test::get_request(port, "/api/v1/envmaps", "Connection: close\r\n")));
  const RawResponse health = c.read_response(), render = c.read_response(), envmaps = c.read_response();
  EXPECT_EQ(health.status, 200);
  EXPECT_EQ(json::parse(health.body)["status"], "ok");
  EXPECT_EQ(render.status, 400) << render.body;
  EXPECT_EQ(envmaps.status, 200) << envmaps.body;
  EXPECT_TRUE(json::parse(envmaps.body)["envmaps"].is_array()) << envmaps.body;
  EXPECT_TRUE(envmaps.has_header("Connection: close"));
  EXPECT_TRUE(c.closed_by_server());
}

TEST(Transport, BadContentLengthsAreAnsweredAtOnce) {
  test::ServerProcess server({"--max-upload-mb", "1"});
  const int port = server.port();
  const auto post_with = [&](const std::string& headers) {
    return round_trip(
        port,
        "POST /api/v1/renders HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n" + headers +
            "\r\n");  // and no body: an answer must not wait for one
  };
  for (const char* value : {"-1", "abc", "1e3", "18446744073709551616", "+5", ""}) {
    const RawResponse r = post_with("Content-Length: " + std::string(value) + "\r\n");
    EXPECT_EQ(r.status, 400) << value << ": " << r.body;
    EXPECT_EQ(error_code(r), "bad_request") << value;
    EXPECT_TRUE(r.has_header("Connection: close")) << value;
  }
  EXPECT_EQ(post_with("Content-Length: 5\r\nContent-Length: 6\r\n").status, 400);
  EXPECT_EQ(post_with("Content-Length: 5\r\nTransfer-Encoding: chunked\r\n").status, 400);
  EXPECT_EQ(post_with("Transfer-Encoding: gzip\r\n").status, 501);
  for (const char* value : {"1048577", "99999999999999999"}) {  // over 1 MiB
    const RawResponse r = post_with("Content-Length: " + std::string(value) + "\r\n");
    EXPECT_EQ(r.status, 413) << value;
    EXPECT_EQ(error_code(r), "payload_too_large") << value;
  }
}

TEST(Transport, ChunkedBodiesWork) {
  const int port = test::shared_server().port();
  const json maps = json::parse(round_trip(port, test::get_request(port, "/api/v1/envmaps")).body)["envmaps"];
  ASSERT_FALSE(maps.empty());
  RawConnection c(port);
  c.send("POST /api/v1/envmaps/" + maps[0]["id"].get<std::string>() +
         "/samples HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
         "Transfer-Encoding: chunked\r\n\r\n"
         "5\r\n{\"cou\r\nA;ext=1\r\nnt\": 3, \"s\r\n7\r\need\": 7\r\n1\r\n}\r\n0\r\n\r\n");
  const RawResponse r = c.read_response();
  ASSERT_EQ(r.status, 200) << r.body;
  const json body = json::parse(r.body);
  EXPECT_EQ(body["count"], 3);
  EXPECT_EQ(body["seed"], 7);
  c.send(test::get_request(port, "/api/v1/health"));  // the connection goes on after the chunked body
  EXPECT_EQ(c.read_response().status, 200);
}

TEST(Transport, AChunkedBodyOverTheLimitGets413AndIsNotHeld) {
  test::ServerProcess server({"--max-upload-mb", "1"});
  const int port = server.port();
  const long before_kib = resident_kib(server.pid());
  RawConnection c(port);
  c.send(
      "POST /api/v1/envmaps?name=big HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: "
      "application/octet-stream\r\n"
      "Transfer-Encoding: chunked\r\n\r\n");
  const std::string chunk = "10000\r\n" + std::string(0x10000, 'x') + "\r\n";  // 64 KiB
  size_t sent = 0;
  while (sent < 1024 && c.send(chunk)) ++sent;  // up to 64 MiB, until the server stops reading
  const RawResponse r = c.read_response();
  EXPECT_EQ(r.status, 413) << r.head << r.body;
  EXPECT_EQ(error_code(r), "payload_too_large");
  const long after_kib = resident_kib(server.pid());
  EXPECT_LT(after_kib - before_kib, 16 * 1024)
      << "resident memory grew from " << before_kib << " to " << after_kib << " KiB";
  EXPECT_EQ(round_trip(port, test::get_request(port, "/api/v1/health")).status, 200);
}

TEST(Transport, HundredThousandHeaderLinesGet431) {
  const int port = test::shared_server().port();
  RawConnection c(port);
  std::string request = "GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\n";
  for (int i = 0; i < 100'000; ++i) request += "X-Filler: 1\r\n";
  c.send(request + "\r\n");  // the server may stop reading (and close) before the end
  const RawResponse r = c.read_response();
  EXPECT_EQ(r.status, 431) << r.body;
  EXPECT_EQ(error_code(r), "header_too_large");

  const std::string long_value(9000, 'v');
  EXPECT_EQ(
      round_trip(port, test::get_request(port, "/api/v1/health", "X-Long: " + long_value + "\r\n")).status,
      431);
  std::string many_bytes;  // under the line count and line length, over the total
  for (int i = 0; i < 90; ++i)
    many_bytes += "X-Big-" + std::to_string(i) + ": " + std::string(1000, 'b') + "\r\n";
  EXPECT_EQ(round_trip(port, test::get_request(port, "/api/v1/health", many_bytes)).status, 431);
  EXPECT_EQ(round_trip(port, test::get_request(port, "/api/v1/health?x=" + std::string(9000, 'q'))).status,
            414);
  EXPECT_EQ(round_trip(port, test::get_request(port, "/api/v1/health")).status, 200);
}

TEST(Transport, RangeHeadersAreIgnored) {
  const int port = test::shared_server().port();
  const RawResponse whole = round_trip(port, test::get_request(port, "/api/v1/openapi.yaml"));
  ASSERT_EQ(whole.status, 200);
  std::string ranges = "Range: bytes=0-0";  // 600 ranges: the line stays under the 8 KiB header line limit
  for (int i = 1; i < 600; ++i)
    ranges.append(",").append(std::to_string(i)).append("-").append(std::to_string(i + 5000));
  const RawResponse ranged =
      round_trip(port, test::get_request(port, "/api/v1/openapi.yaml", ranges + "\r\n"));
  EXPECT_EQ(ranged.status, 200);
  EXPECT_EQ(ranged.body, whole.body);
  const RawResponse bad_range =
      round_trip(port, test::get_request(port, "/api/v1/openapi.yaml", "Range: bytes=x\r\n"));
  EXPECT_EQ(bad_range.status, 200);
  EXPECT_EQ(bad_range.body.size(), whole.body.size());
}

TEST(Transport, AControlByteInThePathGets400) {
  const int port = test::shared_server().port();
  for (const char* path : {"/index.html%00.js", "/api/v1/health%00", "/index.html%0a", "/api%7f/v1/health"}) {
    const RawResponse r = round_trip(port, test::get_request(port, path));
    EXPECT_EQ(r.status, 400) << path;
    EXPECT_EQ(error_code(r), "invalid_path") << path;
    EXPECT_EQ(r.head.find("javascript"), std::string::npos) << path;
  }
  const RawResponse page = round_trip(port, test::get_request(port, "/index.html"));
  EXPECT_EQ(page.status, 200);
  EXPECT_NE(page.head.find("Content-Type: text/html"), std::string::npos) << page.head;
}

// A connection that got one answer. A connection closed just before (the harness's readiness checks)
// counts against the limits until the server has seen it close, so a refusal is retried meanwhile.
std::unique_ptr<RawConnection> served_connection(int port) {
  for (int attempt = 0;; ++attempt) {
    auto c = std::make_unique<RawConnection>(port);
    c->send(test::get_request(port, "/api/v1/health"));
    const int status = c->read_response().status;
    if (status == 200 || attempt == 200) {
      EXPECT_EQ(status, 200);
      return c;
    }
    std::this_thread::sleep_for(10ms);
  }
}

// Opens connections that each got one answer, then one more: refused with 503 and closed.
void expect_refused_after(int port, int open, const std::string& limit_flag) {
  std::vector<std::unique_ptr<RawConnection>> held;
  for (int i = 0; i < open; ++i) held.push_back(served_connection(port));
  RawConnection extra(port);
  extra.send(test::get_request(port, "/api/v1/health"));
  const RawResponse refused = extra.read_response();
  EXPECT_EQ(refused.status, 503);
  EXPECT_EQ(error_code(refused), "too_many_connections");
  EXPECT_NE(json::parse(refused.body)["error"]["message"].get<std::string>().find(limit_flag),
            std::string::npos);
  EXPECT_TRUE(refused.has_header("Connection: close"));
  EXPECT_TRUE(refused.has_header("Retry-After: 1"));
  EXPECT_TRUE(extra.closed_by_server());

  held.pop_back();  // a freed place is served again (once the server has seen the close)
  int status = 0;
  for (int attempt = 0; attempt < 200 && status != 200; ++attempt) {
    std::this_thread::sleep_for(10ms);
    status = round_trip(port, test::get_request(port, "/api/v1/health")).status;
  }
  EXPECT_EQ(status, 200);
}

TEST(Transport, ConnectionsOverThePerClientLimitAreRefused) {
  test::ServerProcess server({"--max-connections-per-client", "4"});
  expect_refused_after(server.port(), 4, "--max-connections-per-client");
}

TEST(Transport, ConnectionsOverTheTotalLimitAreRefused) {
  test::ServerProcess server({"--max-connections", "3"});
  expect_refused_after(server.port(), 3, "--max-connections");
}

TEST(Transport, ASlowHeadGets408AndAnIdleConnectionIsClosed) {
  test::ServerProcess server({"--header-timeout-s", "1", "--keep-alive-timeout-s", "1"});
  const int port = server.port();
  RawConnection slow(port);
  slow.send("GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\n");
  const RawResponse r = slow.read_response();
  EXPECT_EQ(r.status, 408);
  EXPECT_EQ(error_code(r), "request_timeout");

  RawConnection idle(port);
  idle.send(test::get_request(port, "/api/v1/health"));
  EXPECT_EQ(idle.read_response().status, 200);
  EXPECT_TRUE(idle.closed_by_server());
}

TEST(Transport, SigtermClosesIdleSlowAndStreamConnections) {
  test::ServerProcess server(
      {"--keep-alive-timeout-s", "300", "--header-timeout-s", "300", "--shutdown-grace-s", "1"});
  const int port = server.port();
  const std::string id = start_long_render(server);
  RawConnection stream(port), slow(port), idle(port);
  stream.send(test::get_request(port, "/api/v1/renders/" + id + "/events"));
  ASSERT_TRUE(stream.read_until("data: "));
  slow.send("GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\n");
  idle.send(test::get_request(port, "/api/v1/health"));
  ASSERT_EQ(idle.read_response().status, 200);
  server.send_signal(SIGTERM);
  EXPECT_EQ(server.wait_exit(30s), 0);
  EXPECT_TRUE(stream.read_until("event: end"));
  EXPECT_TRUE(idle.closed_by_server());
}

}  // namespace
}  // namespace lp

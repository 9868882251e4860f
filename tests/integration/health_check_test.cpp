// lightprobe-server --health-check URL, the probe a container's HEALTHCHECK runs: exit 0 when the URL
// answers 200, 1 for another status, a refused connection or a server that never answers (within the
// probe's timeout), 2 for a URL it cannot use; --help lists the flag.
#include "server/health_check.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "support/held_port.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using namespace std::chrono_literals;
using test::HeldPort;

test::StartFailure probe(const std::string& url) {
  return test::run_until_exit({"--health-check", url}, 30s);
}

std::string loopback_url(int port, const std::string& path) {
  return "http://127.0.0.1:" + std::to_string(port) + path;
}

TEST(HealthCheck, HealthyServerExitsZero) {
  const auto run = probe(test::default_server().base_url() + "/api/v1/health");
  EXPECT_EQ(run.exit_status, 0) << run.output;
  EXPECT_NE(run.output.find("status 200"), std::string::npos) << run.output;
  EXPECT_LT(run.elapsed, 2s) << run.output;
}

TEST(HealthCheck, OtherStatusExitsOneNamingIt) {
  const auto run = probe(test::default_server().base_url() + "/api/v1/no-such-route");
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find("status 404"), std::string::npos) << run.output;
}

TEST(HealthCheck, RefusedConnectionExitsOne) {
  const HeldPort closed(HeldPort::Mode::BoundOnly);
  const auto run = probe(loopback_url(closed.port(), "/api/v1/health"));
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find("no answer"), std::string::npos) << run.output;
  EXPECT_LT(run.elapsed, 2s) << run.output;
}

TEST(HealthCheck, SilentServerExitsOneAfterTheTimeout) {
  const HeldPort silent;  // the kernel accepts the connection; nothing ever answers
  const auto run = probe(loopback_url(silent.port(), "/api/v1/health"));
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_GE(run.elapsed, server::kHealthCheckTimeout) << run.output;
  EXPECT_LT(run.elapsed, 2 * server::kHealthCheckTimeout + 1s) << run.output;
}

TEST(HealthCheck, UnusableUrlIsABadFlag) {
  for (const std::string url : {"https://127.0.0.1:8080/api/v1/health", "127.0.0.1:8080/api/v1/health",
                                "http://127.0.0.1:99999/", "http:///api/v1/health", "http://host:port/"}) {
    const auto run = probe(url);
    EXPECT_EQ(run.exit_status, 2) << url << ": " << run.output;
    EXPECT_NE(run.output.find("--health-check takes a URL"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(url), std::string::npos) << run.output;
  }
}

TEST(HealthCheck, APathNeedsAPort) {
  const auto run = test::run_until_exit({"--health-check", "/api/v1/ready", "--port", "0"}, 10s);
  EXPECT_EQ(run.exit_status, 2) << run.output;
  EXPECT_NE(run.output.find("needs the server's --port"), std::string::npos) << run.output;
}

TEST(HealthCheck, HelpListsTheFlag) {
  const auto run = test::run_until_exit({"--help"}, 10s);
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_NE(run.output.find("--health-check URL"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace lp

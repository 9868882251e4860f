// Liveness and readiness of the real server: while it loads the maps of --load and its state directory,
// GET /api/v1/health answers 200 and GET /api/v1/ready and the rest of the API 503 not_ready; once they
// are loaded, 200. The map is read from a FIFO, so the test decides when loading ends.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using namespace std::chrono_literals;
using test::Reply;

Reply get(const test::ServerProcess& s, const std::string& path) {
  return test::reply(s.client()->Get(path.c_str()));
}

void expect_not_ready(const Reply& r) {
  EXPECT_EQ(r.status, 503) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "not_ready") << r.body;
  EXPECT_EQ(r.header("Retry-After"), "1");
}

// Writes `bytes` into the FIFO (opening it waits for the server to open it for reading).
void feed(const std::filesystem::path& fifo, const std::vector<uint8_t>& bytes) {
  const int fd = open(fifo.c_str(), O_WRONLY);
  ASSERT_GE(fd, 0);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    ASSERT_GT(n, 0);
    done += size_t(n);
  }
  close(fd);
}

TEST(Readiness, NotReadyWhileTheMapsLoadThenReady) {
  test::TempDir dir;
  const auto fifo = dir.path() / "slow.pfm";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::ServerProcess s({"--load", "slow=" + fifo.string()}, {}, test::StartUntil::Listening);

  EXPECT_EQ(get(s, "/api/v1/health").status, 200);
  expect_not_ready(get(s, "/api/v1/ready"));
  expect_not_ready(get(s, "/api/v1/envmaps"));
  expect_not_ready(test::reply(s.client()->Post("/api/v1/renders", "{}", "application/json")));

  feed(fifo, test::grey_map_pfm(8, 4));
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (get(s, "/api/v1/ready").status != 200 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(10ms);
  const Reply ready = get(s, "/api/v1/ready");
  EXPECT_EQ(ready.status, 200) << ready.body;
  EXPECT_EQ(ready.body_json()["status"], "ready");
  const Reply maps = get(s, "/api/v1/envmaps");
  ASSERT_EQ(maps.status, 200) << maps.body;
  EXPECT_EQ(maps.body_json()["envmaps"].size(), 1u);
  EXPECT_EQ(maps.body_json()["envmaps"][0]["name"], "slow");
}

// The probe a container's HEALTHCHECK runs, `--health-check /api/v1/ready`, finds the port as the server
// does (here LIGHTPROBE_PORT) and passes only once the server is ready.
TEST(Readiness, TheHealthCheckOfAPathPassesOnlyWhenReady) {
  test::TempDir dir;
  const auto fifo = dir.path() / "slow.pfm";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::ServerProcess s({"--load", "slow=" + fifo.string()}, {}, test::StartUntil::Listening);
  const test::Variables port = {{"LIGHTPROBE_PORT", std::to_string(s.port())}};
  const auto probe = [&] { return test::run_until_exit({"--health-check", "/api/v1/ready"}, 30s, port); };

  const auto loading = probe();
  EXPECT_EQ(loading.exit_status, 1) << loading.output;
  EXPECT_NE(loading.output.find("status 503"), std::string::npos) << loading.output;

  feed(fifo, test::grey_map_pfm(8, 4));
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (get(s, "/api/v1/ready").status != 200 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(10ms);
  const auto ready = probe();
  EXPECT_EQ(ready.exit_status, 0) << ready.output;
  EXPECT_NE(ready.output.find("http://127.0.0.1:" + std::to_string(s.port()) + "/api/v1/ready: status 200"),
            std::string::npos)
      << ready.output;
}

TEST(Readiness, AStopWhileLoadingExitsAtOnce) {
  test::TempDir dir;
  const auto fifo = dir.path() / "never.pfm";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::ServerProcess s({"--load", "never=" + fifo.string()}, {}, test::StartUntil::Listening);
  expect_not_ready(get(s, "/api/v1/ready"));
  s.send_signal(SIGTERM);
  EXPECT_EQ(s.wait_exit(5s), 0) << s.log();
}

TEST(Readiness, AMapThatCannotLoadEndsTheStartWithStatusOne) {
  test::TempDir dir;
  const auto run = test::run_until_exit({"--load", "bad=" + (dir.path() / "absent.exr").string(),
                                         "--state-dir", (dir.path() / "state").string()},
                                        10s);
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find("cannot start"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace lp

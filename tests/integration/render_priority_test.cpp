// --render-priority, seen from outside: while a render runs, the kernel's own view of the server's
// threads (/proc/PID/task/TID/stat) shows the render threads 10 nice steps below the main thread (low, the
// default), under SCHED_IDLE (idle), or like every other thread (normal), and the threads answering
// requests untouched. Values are relative to the main thread: the tests may themselves run under `nice`.
#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/thread_sched.hpp"

namespace lp {
namespace {

using json = nlohmann::json;
using namespace std::chrono_literals;

using test::ThreadSched;

// Starts a long render and returns the scheduling of the server's threads once it has passes behind it.
test::ProcessThreads threads_while_rendering(const std::vector<std::string>& flags) {
  test::ServerProcess server(flags);
  const json body = {
      {"envmap", "default"}, {"scene", {{"preset", "sphere"}}}, {"width", 64}, {"height", 64}, {"spp", 4096}};
  const auto submitted =
      test::reply(server.client()->Post("/api/v1/renders", body.dump(), "application/json"));
  EXPECT_EQ(submitted.status, 202) << submitted.body;
  const std::string id = submitted.body_json()["id"];
  for (auto deadline = std::chrono::steady_clock::now() + 120s; std::chrono::steady_clock::now() < deadline;
       std::this_thread::sleep_for(10ms))
    if (test::reply(server.client()->Get(("/api/v1/renders/" + id).c_str())).body_json()["spp_done"] >= 2)
      break;
  auto threads = test::threads_of(server.pid());
  server.client()->Delete(("/api/v1/renders/" + id).c_str());
  return threads;
}

TEST(RenderPriority, LowByDefaultIsTenNiceStepsBelowTheServerForRenderThreadsOnly) {
  const auto threads = threads_while_rendering({"--threads", "2"});
  const int low = std::min(threads.main.nice + 10, 19);
  test::expect_render_threads_at(threads, {low, SCHED_OTHER}, 2);
}

TEST(RenderPriority, IdleIsSchedIdle) {
  const auto threads = threads_while_rendering({"--threads", "2", "--render-priority", "idle"});
  test::expect_render_threads_at(threads, {threads.main.nice, SCHED_IDLE}, 2);
}

TEST(RenderPriority, NormalLeavesEveryThreadAlike) {
  const auto threads = threads_while_rendering({"--threads", "2", "--render-priority", "normal"});
  EXPECT_EQ(std::count(threads.all.begin(), threads.all.end(), threads.main), int(threads.all.size()));
}

TEST(RenderPriority, AnUnknownNameIsABadFlag) {
  const auto run = test::run_until_exit({"--render-priority", "realtime"}, 10s);
  EXPECT_EQ(run.exit_status, 2) << run.output;
  EXPECT_NE(run.output.find("--render-priority takes one of low|idle|normal, got 'realtime'"),
            std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace lp

// --render-priority, seen from outside: while a render runs, the kernel's own view of the server's
// threads (/proc/PID/task/TID/stat) shows the render threads 10 nice steps below the main thread (low, the
// default), under SCHED_IDLE (idle), or like every other thread (normal), and the threads answering
// requests untouched. Values are relative to the main thread: the tests may themselves run under `nice`.
#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using json = nlohmann::json;
using namespace std::chrono_literals;

struct ThreadSched {
  int nice;
  int policy;
  bool operator==(const ThreadSched&) const = default;
};

// Field 19 of a stat line is the nice value and field 41 the policy; the name (field 2) may hold spaces,
// so the fields are counted after its closing parenthesis.
ThreadSched thread_sched(const std::filesystem::path& stat) {
  std::ifstream in(stat);
  std::string line;
  std::getline(in, line);
  std::istringstream fields(line.substr(line.rfind(')') + 2));
  std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
  return {std::stoi(f.at(19 - 3)), std::stoi(f.at(41 - 3))};
}

struct ServerThreads {
  ThreadSched main;
  std::vector<ThreadSched> all;
};

ServerThreads threads_of(int pid) {
  const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
  ServerThreads out{thread_sched(tasks / std::to_string(pid) / "stat"), {}};
  for (const auto& task : std::filesystem::directory_iterator(tasks)) {
    try {
      out.all.push_back(thread_sched(task.path() / "stat"));
    } catch (const std::exception&) {  // the thread ended while it was read
    }
  }
  return out;
}

// Starts a long render and returns the scheduling of the server's threads once it has passes behind it.
ServerThreads threads_while_rendering(const std::vector<std::string>& flags) {
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
  auto threads = threads_of(server.pid());
  server.client()->Delete(("/api/v1/renders/" + id).c_str());
  return threads;
}

int count(const std::vector<ThreadSched>& threads, ThreadSched sched) {
  return int(std::count(threads.begin(), threads.end(), sched));
}

// The server's threads at `render` and at the main thread's scheduling, checking that no thread has
// any other and that at least `renderers` have `render` (the job's runner and a worker).
void expect_render_threads_at(const ServerThreads& threads, ThreadSched render, int renderers) {
  EXPECT_EQ(threads.main.policy, SCHED_OTHER);
  const int at_render = count(threads.all, render);
  const int at_main = count(threads.all, threads.main);
  EXPECT_GE(at_render, renderers);
  EXPECT_GE(at_main, 1);
  EXPECT_EQ(render == threads.main ? at_main : at_render + at_main, int(threads.all.size()));
}

TEST(RenderPriority, LowByDefaultIsTenNiceStepsBelowTheServerForRenderThreadsOnly) {
  const auto threads = threads_while_rendering({"--threads", "2"});
  const int low = std::min(threads.main.nice + 10, 19);
  expect_render_threads_at(threads, {low, SCHED_OTHER}, 2);
}

TEST(RenderPriority, IdleIsSchedIdle) {
  const auto threads = threads_while_rendering({"--threads", "2", "--render-priority", "idle"});
  expect_render_threads_at(threads, {threads.main.nice, SCHED_IDLE}, 2);
}

TEST(RenderPriority, NormalLeavesEveryThreadAlike) {
  const auto threads = threads_while_rendering({"--threads", "2", "--render-priority", "normal"});
  EXPECT_EQ(count(threads.all, threads.main), int(threads.all.size()));
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

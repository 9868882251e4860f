// --log-level and --access-log-sample on the real server: how many access lines a known number of
// requests leaves in its output, and that a 5xx answer is logged whatever the sampling.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "support/server_process.hpp"

namespace lp {
namespace {

using json = nlohmann::json;

int count_lines(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  return int(std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

const char* const kHealthLine = R"(info GET /api/v1/health 200 [0-9.]+ ms)";

void get_health(const test::ServerProcess& s, int times) {
  auto c = s.client();
  for (int i = 0; i < times; ++i) ASSERT_EQ(c->Get("/api/v1/health")->status, 200);
}

// Stops the server so that its output is complete.
std::string output_after_stop(test::ServerProcess& s) {
  s.send_signal(SIGTERM);
  EXPECT_EQ(s.wait_exit(std::chrono::seconds(30)), 0);
  return s.log();
}

// A render that keeps the only running slot busy, and one more that finds the queue full: 503.
void provoke_503(const test::ServerProcess& s) {
  auto c = s.client();
  const json body = {{"envmap", "default"},
                     {"scene", {{"preset", "sphere"}}},
                     {"width", 512},
                     {"height", 512},
                     {"spp", 4096}};
  const auto first = c->Post("/api/v1/renders", body.dump(), "application/json");
  ASSERT_EQ(first->status, 202) << first->body;
  const auto full = c->Post("/api/v1/renders", body.dump(), "application/json");
  ASSERT_EQ(full->status, 503) << full->body;
  const std::string id = json::parse(first->body)["id"];
  EXPECT_EQ(c->Delete(("/api/v1/renders/" + id).c_str())->status, 202);
}

const std::vector<std::string> kOneRenderSlot = {"--max-running-jobs", "1", "--max-queued-jobs", "0"};

TEST(Logging, EveryRequestByDefault) {
  test::ServerProcess s;
  get_health(s, 7);
  EXPECT_EQ(count_lines(output_after_stop(s), kHealthLine), 7);
}

TEST(Logging, SampledOneInN) {
  test::ServerProcess s({"--access-log-sample", "4"});
  get_health(s, 12);
  EXPECT_EQ(count_lines(output_after_stop(s), kHealthLine), 3);
}

TEST(Logging, AccessLogOffStillLogsServerErrors) {
  std::vector<std::string> args = {"--access-log-sample", "0"};
  args.insert(args.end(), kOneRenderSlot.begin(), kOneRenderSlot.end());
  test::ServerProcess s(args);
  get_health(s, 5);
  provoke_503(s);
  const std::string out = output_after_stop(s);
  EXPECT_EQ(count_lines(out, kHealthLine), 0);
  EXPECT_EQ(count_lines(out, R"(info (GET|POST|DELETE) )"), 0) << out;
  EXPECT_EQ(count_lines(out, R"(error POST /api/v1/renders 503 [0-9.]+ ms)"), 1) << out;
}

TEST(Logging, LevelWarnHidesInfoButNotErrors) {
  std::vector<std::string> args = {"--log-level", "warn"};
  args.insert(args.end(), kOneRenderSlot.begin(), kOneRenderSlot.end());
  test::ServerProcess s(args);  // its port is still printed
  get_health(s, 5);
  provoke_503(s);
  const std::string out = output_after_stop(s);
  EXPECT_EQ(count_lines(out, R"( info )"), 0) << out;
  EXPECT_EQ(count_lines(out, R"(error POST /api/v1/renders 503 [0-9.]+ ms)"), 1) << out;
}

TEST(Logging, LevelOffWritesNothingButTheAddress) {
  test::ServerProcess s({"--log-level", "off"});
  get_health(s, 3);
  const std::string out = output_after_stop(s);
  EXPECT_EQ(count_lines(out, R"(\n)"), 1) << out;
  EXPECT_EQ(count_lines(out, R"(^lightprobe-server \S+ listening on http://127\.0\.0\.1:[0-9]+\n$)"), 1)
      << out;
}

TEST(Logging, BadValuesAreRefusedAtStart) {
  test::StartFailure bad = test::run_until_exit({"--log-level", "verbose"}, std::chrono::seconds(10));
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.output.find("--log-level takes one of trace|debug|info|warn|error|off, got 'verbose'"),
            std::string::npos)
      << bad.output;
  bad = test::run_until_exit({"--access-log-sample", "-1"}, std::chrono::seconds(10));
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.output.find("--access-log-sample takes an integer"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace lp

// --log-level and --access-log-sample on the real server: how many access lines a known number of
// requests leaves in its output, and that a 5xx answer is logged whatever the sampling.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
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

// --log-format json: every line is one JSON object with time (UTC, ms), level and message; access lines
// add the request's fields.
TEST(Logging, JsonLinesCarryTheRequestsFields) {
  test::ServerProcess s({"--log-format", "json"});
  get_health(s, 2);
  ASSERT_EQ(s.client()->Get("/api/v1/envmaps/absent", {{"X-Request-Id", "abc-1"}})->status, 404);
  const std::string out = output_after_stop(s);
  const std::regex time(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z)");
  int lines = 0, access = 0;
  bool listening = false;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line); ++lines) {
    SCOPED_TRACE(line);
    const json j = json::parse(line);  // throws (fails the test) on a line that is not one JSON object
    ASSERT_TRUE(j.is_object());
    if (j.value("path", "") == "/api/v1/ready") continue;  // the test's start waiting for the server
    EXPECT_TRUE(std::regex_match(j["time"].get<std::string>(), time));
    EXPECT_TRUE(j["level"] == "info" || j["level"] == "warning") << j["level"];
    ASSERT_TRUE(j["message"].is_string());
    listening |= j["message"].get<std::string>().find("listening on http://127.0.0.1:") != std::string::npos;
    if (!j.contains("request_id")) continue;
    ++access;
    EXPECT_EQ(j["method"], "GET");
    EXPECT_EQ(j["client"], "127.0.0.1");
    EXPECT_GE(j["duration_ms"].get<double>(), 0);
    const std::string begins = j["method"].get<std::string>() + " " + j["path"].get<std::string>() + " " +
                               std::to_string(j["status"].get<int>()) + " ";
    EXPECT_TRUE(j["message"].get<std::string>().starts_with(begins));
    if (j["path"] == "/api/v1/envmaps/absent") {
      EXPECT_EQ(j["status"], 404);
      EXPECT_EQ(j["request_id"], "abc-1");
      EXPECT_EQ(j["route"], "/api/v1/envmaps/{id}");
    } else {
      EXPECT_EQ(j["status"], 200);
      EXPECT_EQ(j["route"], "/api/v1/health");
      EXPECT_EQ(j["request_id"].get<std::string>().size(), 16u);
    }
  }
  EXPECT_GT(lines, 5);
  EXPECT_GE(access, 3);
  EXPECT_TRUE(listening);
}

TEST(Logging, BadValuesAreRefusedAtStart) {
  test::StartFailure bad = test::run_until_exit({"--log-level", "verbose"}, std::chrono::seconds(10));
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.output.find("--log-level takes one of trace|debug|info|warn|error|off, got 'verbose'"),
            std::string::npos)
      << bad.output;
  bad = test::run_until_exit({"--log-format", "xml"}, std::chrono::seconds(10));
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.output.find("--log-format takes one of text|json, got 'xml'"), std::string::npos)
      << bad.output;
  bad = test::run_until_exit({"--access-log-sample", "-1"}, std::chrono::seconds(10));
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.output.find("--access-log-sample takes an integer"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace lp

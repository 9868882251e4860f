// Every flag of the real server can also be set by an environment variable, LIGHTPROBE_<FLAG>: the
// variables set what their flags set, a flag on the command line wins over its variable, a bad value
// names the variable, and --help and the README list every variable.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;

int samples_status(const test::ServerProcess& s, int count) {
  const json body = {{"count", count}};
  return s.client()->Post("/api/v1/envmaps/default/samples", body.dump(), "application/json")->status;
}

std::set<std::string> map_names(const test::ServerProcess& s) {
  std::set<std::string> names;
  const auto r = test::reply(s.client()->Get("/api/v1/envmaps"));
  EXPECT_EQ(r.status, 200) << r.body;
  const json body = r.body_json();
  for (const auto& m : body["envmaps"]) names.insert(m["name"].get<std::string>());
  return names;
}

std::string map_entry(const std::string& name, const std::string& file) {
  return name + "=" + test::envmap_path(file).string();
}

TEST(Environment, VariablesSetWhatTheirFlagsSet) {
  test::ServerProcess s({}, {{"LIGHTPROBE_MAX_SAMPLES", "5"},
                             {"LIGHTPROBE_LOAD", map_entry("default", "forest.pfm") + ", " +
                                                     map_entry("studio", "studio.hdr")}});
  EXPECT_EQ(samples_status(s, 5), 200);
  EXPECT_EQ(samples_status(s, 6), 400);
  EXPECT_EQ(map_names(s), (std::set<std::string>{"default", "studio"}));
}

TEST(Environment, TheCommandLineWinsOverItsVariable) {
  // LIGHTPROBE_PORT=1 would fail to bind: the test's --port 0 wins.
  test::ServerProcess s({"--max-samples", "7", "--load", map_entry("default", "studio.hdr")},
                        {{"LIGHTPROBE_PORT", "1"},
                         {"LIGHTPROBE_MAX_SAMPLES", "5"},
                         {"LIGHTPROBE_LOAD", map_entry("forest", "forest.pfm")},
                         {"LIGHTPROBE_MAX_LIGHTS", ""}});  // empty: unset, the default applies
  EXPECT_EQ(samples_status(s, 7), 200);
  EXPECT_EQ(samples_status(s, 8), 400);
  EXPECT_EQ(map_names(s), (std::set<std::string>{"default"}));
  const json cut = {{"count", 1024}};
  EXPECT_EQ(s.client()->Post("/api/v1/envmaps/default/median-cut", cut.dump(), "application/json")->status,
            200);
}

TEST(Environment, ABadValueNamesItsVariable) {
  for (const auto& [name, value] : test::Variables{{"LIGHTPROBE_MAX_SAMPLES", "0"},
                                                   {"LIGHTPROBE_LOG_LEVEL", "loud"},
                                                   {"LIGHTPROBE_RESUME_INTERRUPTED", "maybe"},
                                                   {"LIGHTPROBE_LOAD", "no-equals-sign"}}) {
    const auto run = test::run_until_exit({}, 10s, {{name, value}});
    EXPECT_EQ(run.exit_status, 2) << name << ": " << run.output;
    EXPECT_NE(run.output.find("(from " + name + ")"), std::string::npos) << run.output;
  }
}

// Every flag --help lists (but the actions --list-routes, --health-check, --version and --help) has its
// variable listed there and in the README.
TEST(Environment, HelpAndReadmeListEveryVariable) {
  const auto help = test::run_until_exit({"--help"}, 10s);
  ASSERT_EQ(help.exit_status, 0) << help.output;
  std::ifstream in(LIGHTPROBE_README);
  const std::string readme{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(readme.size(), 1000u);
  const std::regex flag(R"(\n  --([a-z][a-z0-9-]*))");
  int flags = 0;
  for (auto it = std::sregex_iterator(help.output.begin(), help.output.end(), flag);
       it != std::sregex_iterator(); ++it) {
    std::string name = (*it)[1];
    if (name == "list-routes" || name == "health-check" || name == "version" || name == "help") continue;
    ++flags;
    std::string variable = "LIGHTPROBE_";
    for (const char c : name) variable += c == '-' ? '_' : char(std::toupper(c));
    EXPECT_TRUE(std::regex_search(help.output, std::regex("\\b" + variable + "\\b"))) << variable;
    EXPECT_TRUE(std::regex_search(readme, std::regex("\\b" + variable + "\\b"))) << variable;
  }
  EXPECT_GT(flags, 30);
}

}  // namespace
}  // namespace lp

// Logging in to Redis: rediss:// (TLS, the server's certificate verified), a password from the --redis
// URL, --redis-password-file or LIGHTPROBE_REDIS_PASSWORD (for the default user and for an ACL user) and
// a database number, each against a real redis-server on loopback, with a coordinator (--role api) and a
// worker (--role worker), real lightprobe-server processes. The password is never in their output, nor in
// what they answer over HTTP.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/poll_until.hpp"
#include "support/redis_process.hpp"
#include "support/render_polling.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

using json = nlohmann::json;
using namespace std::chrono_literals;

constexpr int kSize = 48, kSpp = 8;
constexpr const char* kPassword = "c0rrect-h0rse_battery";

std::string body() {
  return json{{"envmap", "default"}, {"scene", {{"preset", "materials"}}},
              {"width", kSize},      {"height", kSize},
              {"spp", kSpp},         {"seed", 3}}
      .dump();
}

// The final status of a render the api server accepted.
json render(const test::ServerProcess& api) {
  const auto r = api.client()->Post("/api/v1/renders", body(), "application/json");
  if (!r || r->status != 202) {
    ADD_FAILURE() << (r ? r->body : "no answer");
    return {};
  }
  const std::string id = json::parse(r->body)["id"];
  return test::poll_until(
      "render " + id,
      [&] {
        const auto s = api.client()->Get("/api/v1/renders/" + id);
        return s && s->status == 200 ? json::parse(s->body) : json{{"status", "?"}};
      },
      test::job_ended);
}

// An api server and a worker, each with `flags` and `variables` besides their role.
struct Pair {
  std::unique_ptr<test::ServerProcess> api, worker;
  Pair(std::vector<std::string> flags, const test::Variables& variables = {}) {
    flags.insert(flags.end(), {"--redis-item-spp", "4", "--log-level", "debug"});
    auto with = [&](std::vector<std::string> role) {
      role.insert(role.end(), flags.begin(), flags.end());
      return role;
    };
    api = std::make_unique<test::ServerProcess>(with({"--role", "api"}), variables);
    worker = std::make_unique<test::ServerProcess>(with({"--role", "worker", "--threads", "1"}), variables);
  }

  // Neither server shows the password: in its output, its health, readiness and metrics.
  void expect_no_password() const {
    for (const auto* s : {api.get(), worker.get()}) {
      EXPECT_EQ(s->log().find(kPassword), std::string::npos) << s->log();
      for (const char* path : {"/api/v1/health", "/api/v1/ready", "/metrics"}) {
        const auto r = s->client()->Get(path);
        ASSERT_TRUE(r) << path;
        EXPECT_EQ(r->body.find(kPassword), std::string::npos) << path;
      }
    }
  }
};

void expect_done(const json& st) {
  EXPECT_EQ(st["status"], "done") << st.dump();
  EXPECT_EQ(st["spp_done"], kSpp);
  EXPECT_EQ(st["samples"], uint64_t(kSpp) * kSize * kSize);
}

// The keys of one database of the Redis, by redis-cli.
std::string keys_in(const test::RedisProcess& redis, int db, const std::string& user_password = "") {
  std::string command = "redis-cli -p " + std::to_string(redis.port()) + " -n " + std::to_string(db);
  if (!user_password.empty()) command += " --no-auth-warning -a " + user_password;
  command += " --scan --pattern 'lightprobe:*'";
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
    pclose(pipe);
  }
  return out;
}

TEST(RedisLogin, ASplitRenderRunsOverTls) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis({.tls = true, .args = {}});
  ASSERT_TRUE(redis.url().starts_with("rediss://"));
  Pair pair({"--redis", redis.url(), "--redis-tls-ca", redis.tls_files().ca_cert.string()});
  expect_done(render(*pair.api));
  EXPECT_TRUE(pair.worker->wait_log("samples 0-4 done"));
}

TEST(RedisLogin, ACertificateOfAnotherCaIsRefusedNamingWhy) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis({.tls = true, .args = {}});
  test::TempDir other;
  const auto other_ca = test::make_tls_files(other.path()).ca_cert;
  test::ServerProcess api({"--redis", redis.url(), "--redis-tls-ca", other_ca.string(), "--role", "api"});
  const json st = render(api);
  EXPECT_EQ(st["status"], "failed") << st.dump();
  const std::string message = st["error"].value("message", "");
  // OpenSSL's reason: the chain ends in a self-signed CA the file does not hold.
  EXPECT_NE(
      message.find("cannot connect to " + redis.url() +
                   ": TLS: the server's certificate was refused: self-signed certificate in certificate "
                   "chain (trusted: the CAs of --redis-tls-ca " +
                   other_ca.string() + ")"),
      std::string::npos)
      << message;
  // Without --redis-tls-ca the system's CAs do not know the test's CA either.
  test::ServerProcess system_cas({"--redis", redis.url(), "--role", "api"});
  const json without = render(system_cas);
  EXPECT_EQ(without["status"], "failed");
  EXPECT_NE(
      without["error"].value("message", "").find("(trusted: the system's CA store; see --redis-tls-ca)"),
      std::string::npos)
      << without.dump();
}

TEST(RedisLogin, APasswordFromTheUrlAFileOrTheVariableLogsIn) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis({.args = {"--requirepass", kPassword}});
  const std::string address = "127.0.0.1:" + std::to_string(redis.port());
  test::TempDir dir;
  const auto file = dir.path() / "redis-password";
  std::ofstream(file) << kPassword << "\n";
  {
    Pair url({"--redis", "redis://:" + std::string(kPassword) + "@" + address});
    expect_done(render(*url.api));
    url.expect_no_password();
  }
  {
    Pair from_file({"--redis", "redis://" + address, "--redis-password-file", file.string()});
    expect_done(render(*from_file.api));
    from_file.expect_no_password();
  }
  Pair variable({"--redis", "redis://" + address}, {{"LIGHTPROBE_REDIS_PASSWORD", kPassword}});
  expect_done(render(*variable.api));
  variable.expect_no_password();
}

TEST(RedisLogin, AnAclUserLogsInWithItsName) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis({.args = {"--user", "default", "off", "--user", "render-farm", "on",
                                     std::string(">") + kPassword, "~*", "&*", "+@all"}});
  Pair pair({"--redis",
             "redis://render-farm:" + std::string(kPassword) + "@127.0.0.1:" + std::to_string(redis.port())});
  expect_done(render(*pair.api));
  pair.expect_no_password();
  EXPECT_NE(pair.worker->log().find("render-farm:***@127.0.0.1"), std::string::npos) << pair.worker->log();
}

TEST(RedisLogin, AWrongPasswordIsRefusedNamingTheServerNotThePassword) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis({.args = {"--requirepass", "the-right-one"}});
  test::ServerProcess api({"--redis", "redis://127.0.0.1:" + std::to_string(redis.port()), "--role", "api"},
                          {{"LIGHTPROBE_REDIS_PASSWORD", kPassword}});
  const json st = render(api);
  EXPECT_EQ(st["status"], "failed") << st.dump();
  const std::string message = st["error"].value("message", "");
  EXPECT_NE(
      message.find("AUTH refused by redis://:***@127.0.0.1:" + std::to_string(redis.port()) + ": WRONGPASS"),
      std::string::npos)
      << message;
  EXPECT_EQ(message.find(kPassword), std::string::npos) << message;
  EXPECT_EQ(api.log().find(kPassword), std::string::npos) << api.log();
}

TEST(RedisLogin, TheDatabaseNumberSelectsWhereTheKeysGo) {
  SKIP_WITHOUT_REDIS();
  test::RedisProcess redis;
  Pair pair({"--redis", redis.url() + "/5"});
  expect_done(render(*pair.api));
  // The worker's heartbeat and the render's partials stay a while after it ended.
  EXPECT_NE(keys_in(redis, 5), "");
  EXPECT_EQ(keys_in(redis, 0), "");
}

}  // namespace
}  // namespace lp

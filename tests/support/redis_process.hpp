#pragma once
// A real redis-server for a test: on a free loopback port, its data and append-only file in a fresh
// directory (appendonly yes), stopped at the end. restart() stops it (SIGTERM: it writes its append-only
// file) and starts it again on the same port and directory; restart_empty() starts it without its data.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace lp::test {

// The path of redis-server, nullopt when it is not installed (the test then skips).
std::optional<std::filesystem::path> redis_server_binary();

#define SKIP_WITHOUT_REDIS()              \
  if (!::lp::test::redis_server_binary()) \
  GTEST_SKIP() << "redis-server is not installed (scripts/setup --test installs it)"

// A CA and a server certificate it signed (for 127.0.0.1 and localhost), PEM files made by the openssl
// command in `dir`.
struct TlsFiles {
  std::filesystem::path ca_cert, server_cert, server_key;
};
TlsFiles make_tls_files(const std::filesystem::path& dir);

struct RedisSetup {
  bool tls = false;
  std::vector<std::string> args;  // more redis-server flags, e.g. {"--requirepass", "secret"}
};

class RedisProcess {
 public:
  // Throws std::runtime_error if it does not answer within 10 s.
  explicit RedisProcess(RedisSetup setup = {});
  ~RedisProcess();
  RedisProcess(const RedisProcess&) = delete;
  RedisProcess& operator=(const RedisProcess&) = delete;

  int port() const { return port_; }
  std::string url() const {
    return (setup_.tls ? "rediss://" : "redis://") + std::string("127.0.0.1:") + std::to_string(port_);
  }
  const TlsFiles& tls_files() const { return tls_; }  // with RedisSetup::tls
  std::string log() const;                            // redis-server's own log
  void stop();
  void start();
  void restart() {
    stop();
    start();
  }
  // Kills it (SIGKILL) and deletes its data, then starts it empty: a Redis that lost every write.
  void restart_empty();

 private:
  TempDir dir_;
  RedisSetup setup_;
  TlsFiles tls_;
  int port_ = 0;
  int pid_ = -1;
};

}  // namespace lp::test

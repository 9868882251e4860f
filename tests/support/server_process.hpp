#pragma once
// Starts the real lightprobe-server binary on a free loopback port (--port 0; the port is read
// from the line the server prints on start), by default waits until it is ready (GET /api/v1/ready
// answers 200: its maps and state are loaded), and stops it at the end of the test. Unless the flags name
// a --state-dir, each server gets a fresh one of its own, removed at the end.
#include <httplib.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "support/child_process.hpp"  // Variables, e.g. {{"LIGHTPROBE_MAX_SAMPLES", "5"}}
#include "support/temp_dir.hpp"

namespace lp::test {

// How far the constructor waits: until the server is ready, or only until it listens.
enum class StartUntil { Ready, Listening };

class ServerProcess {
 public:
  // `args` are extra flags, e.g. {"--load", "forest=/abs/forest.exr", "--max-samples", "1000"};
  // `launcher` a command the server runs under (e.g. SmallDisk::launcher()), which execs it.
  explicit ServerProcess(const std::vector<std::string>& args = {}, const Variables& variables = {},
                         StartUntil until = StartUntil::Ready, const std::vector<std::string>& launcher = {});
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  int pid() const { return pid_; }
  std::string base_url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  // A client with generous timeouts, bound to this server.
  std::unique_ptr<httplib::Client> client() const;
  bool alive() const;             // the process has not exited
  void wait_until_ready() const;  // until GET /api/v1/ready answers 200; throws after 60 s
  const std::string& log_path() const { return log_path_; }
  std::string log() const;  // the server's output so far
  // The server logs from a thread of its own, so a line may reach the log after the reply that follows
  // it: polls the log until it holds `what` at least `times` times; false after `limit`.
  bool wait_log(const std::string& what, int times = 1,
                std::chrono::milliseconds limit = std::chrono::seconds(60)) const;

  void send_signal(int signal) const;
  // Waits for the process to exit: its exit status, or -N if signal N ended it; nullopt if it is still
  // running after `timeout`. After it, the destructor has nothing left to stop.
  std::optional<int> wait_exit(std::chrono::milliseconds timeout);

 private:
  int pid_ = -1;
  int port_ = 0;
  std::string log_path_;
  std::filesystem::path own_state_dir_;
};

// A server run that is expected to fail at start: its exit status (or -N for signal N), how long it
// took, and its output. Fails the test if it is still running after `timeout` (then killed).
struct StartFailure {
  int exit_status = 0;
  std::chrono::duration<double> elapsed{};
  std::string output;
};
StartFailure run_until_exit(const std::vector<std::string>& args, std::chrono::milliseconds timeout,
                            const Variables& variables = {});

// A server shared by all tests of a test binary that need no special flags (started on first use,
// with forest, studio and the other real maps preloaded under their file stems, e.g. "forest_exr").
ServerProcess& shared_server();
// A server started with no flags, so it holds only the built-in map "default"; shared the same way.
ServerProcess& default_server();

}  // namespace lp::test

#include "support/server_process.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <thread>

#include "support/child_process.hpp"
#include "support/test_data.hpp"

namespace lp::test {
namespace {

int wait_for_port(const std::string& log_path, int pid) {
  const std::regex listening(R"(listening on http://[^:]+:(\d+))");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in(log_path);
    std::string line;
    while (std::getline(in, line)) {
      std::smatch m;
      if (std::regex_search(line, m, listening)) return std::stoi(m[1]);
    }
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid)
      throw std::runtime_error("server exited on start; log: " + log_path);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  throw std::runtime_error("server did not report its port within 60 s; log: " + log_path);
}

// Starts the server with its output to a new log file; returns the pid and sets `log_path`.
int spawn(const std::vector<std::string>& args, std::string& log_path, const Variables& variables,
          const std::vector<std::string>& launcher = {}) {
  char tmpl[] = "/tmp/lightprobe-server-XXXXXX.log";
  const int fd = mkstemps(tmpl, 4);
  if (fd < 0) throw std::runtime_error("mkstemps failed");
  log_path = tmpl;

  std::vector<std::string> argv = launcher;
  argv.insert(argv.end(), {LIGHTPROBE_SERVER_BIN, "--host", "127.0.0.1", "--port", "0"});
  argv.insert(argv.end(), args.begin(), args.end());
  const int pid = start_process(argv, fd, fd, {}, variables);
  close(fd);
  return pid;
}

std::optional<int> wait_for_exit(int pid, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  do {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return exit_status_of(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  } while (std::chrono::steady_clock::now() < deadline);
  return std::nullopt;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool names_state_dir(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--state-dir") != args.end();
}

}  // namespace

ServerProcess::ServerProcess(const std::vector<std::string>& args, const Variables& variables,
                             StartUntil until, const std::vector<std::string>& launcher) {
  std::vector<std::string> all = args;
  if (!names_state_dir(args)) {
    own_state_dir_ = make_temp_dir();
    all.insert(all.end(), {"--state-dir", own_state_dir_.string()});
  }
  pid_ = spawn(all, log_path_, variables, launcher);
  port_ = wait_for_port(log_path_, pid_);
  if (until != StartUntil::Ready) return;
  try {
    wait_until_ready();
  } catch (...) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    throw;
  }
}

void ServerProcess::wait_until_ready() const {
  auto c = client();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    if (const auto r = c->Get("/api/v1/ready"); r && r->status == 200) return;
    if (!alive()) throw std::runtime_error("server exited while loading; log: " + log_path_);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  throw std::runtime_error("server was not ready within 60 s; log: " + log_path_);
}

ServerProcess::~ServerProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    if (!wait_for_exit(pid_, std::chrono::seconds(5))) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  std::error_code ec;
  if (!own_state_dir_.empty()) std::filesystem::remove_all(own_state_dir_, ec);
}

std::string ServerProcess::log() const {
  return read_text(log_path_);
}

bool ServerProcess::wait_log(const std::string& what, int times, std::chrono::milliseconds limit) const {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  for (;;) {
    const std::string text = log();
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos && n < times; at = text.find(what, at + 1)) ++n;
    if (n >= times) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void ServerProcess::send_signal(int signal) const {
  if (pid_ > 0) kill(pid_, signal);
}

std::optional<int> ServerProcess::wait_exit(std::chrono::milliseconds timeout) {
  if (pid_ <= 0) return std::nullopt;
  const auto status = wait_for_exit(pid_, timeout);
  if (status) pid_ = -1;
  return status;
}

StartFailure run_until_exit(const std::vector<std::string>& args, std::chrono::milliseconds timeout,
                            const Variables& variables) {
  std::string log_path;
  const auto start = std::chrono::steady_clock::now();
  const int pid = spawn(args, log_path, variables);
  StartFailure result;
  const auto status = wait_for_exit(pid, timeout);
  result.elapsed = std::chrono::steady_clock::now() - start;
  if (!status) {
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    ADD_FAILURE() << "the server was still running after " << timeout.count() << " ms";
  }
  result.exit_status = status.value_or(-SIGKILL);
  result.output = read_text(log_path);
  return result;
}

std::unique_ptr<httplib::Client> ServerProcess::client() const {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", port_);
  c->set_connection_timeout(10);
  c->set_read_timeout(120);
  c->set_write_timeout(120);
  return c;
}

bool ServerProcess::alive() const {
  return pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0;
}

ServerProcess& shared_server() {
  static ServerProcess server([] {
    std::vector<std::string> args = {"--data-dir", LIGHTPROBE_TEST_DATA};
    for (const auto& file : real_envmap_files()) {
      std::string stem = file;
      std::replace(stem.begin(), stem.end(), '.', '_');
      args.push_back("--load");
      args.push_back(stem + "=" + envmap_path(file).string());
    }
    return args;
  }());
  return server;
}

ServerProcess& default_server() {
  static ServerProcess server;
  return server;
}

}  // namespace lp::test

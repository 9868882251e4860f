#include "support/server_process.hpp"

#include <fcntl.h>
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
    if (waitpid(pid, &status, WNOHANG) == pid) throw std::runtime_error("server exited on start; log: " + log_path);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  throw std::runtime_error("server did not report its port within 60 s; log: " + log_path);
}

}  // namespace

ServerProcess::ServerProcess(const std::vector<std::string>& args) {
  char tmpl[] = "/tmp/lightprobe-server-XXXXXX.log";
  const int fd = mkstemps(tmpl, 4);
  if (fd < 0) throw std::runtime_error("mkstemps failed");
  log_path_ = tmpl;

  std::vector<std::string> argv_strings = {LIGHTPROBE_SERVER_BIN, "--host", "127.0.0.1", "--port", "0"};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);

  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(fd);
  port_ = wait_for_port(log_path_, pid_);
}

ServerProcess::~ServerProcess() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  for (int i = 0; i < 200; ++i) {
    if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
}

std::unique_ptr<httplib::Client> ServerProcess::client() const {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", port_);
  c->set_connection_timeout(10);
  c->set_read_timeout(120);
  c->set_write_timeout(120);
  return c;
}

bool ServerProcess::alive() const { return pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0; }

ServerProcess& shared_server() {
  static ServerProcess server([] {
    std::vector<std::string> args = {"--data-dir", shared_data().string()};
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

}  // namespace lp::test

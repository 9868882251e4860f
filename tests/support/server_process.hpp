#pragma once
// Starts the real lightprobe-server binary on a free loopback port (--port 0; the port is read
// from the line the server prints on start) and stops it at the end of the test.
#include <memory>
#include <string>
#include <vector>

#include <httplib.h>

namespace lp::test {

class ServerProcess {
 public:
  // `args` are extra flags, e.g. {"--load", "forest=/abs/forest.exr", "--max-samples", "1000"}.
  explicit ServerProcess(const std::vector<std::string>& args = {});
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  std::string base_url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  // A client with generous timeouts, bound to this server.
  std::unique_ptr<httplib::Client> client() const;
  bool alive() const;  // the process has not exited
  int pid() const { return pid_; }
  const std::string& log_path() const { return log_path_; }

 private:
  int pid_ = -1;
  int port_ = 0;
  std::string log_path_;
};

// A server shared by all tests of a test binary that need no special flags (started on first use,
// with forest, studio and the other real maps preloaded under their file stems, e.g. "forest_exr").
ServerProcess& shared_server();

}  // namespace lp::test

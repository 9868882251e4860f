#include "support/redis_process.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "support/child_process.hpp"

namespace lp::test {
namespace {

using namespace std::chrono_literals;

// A port nothing listens on now (the kernel's choice for port 0).
int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), len) != 0 ||
      getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    close(fd);
    throw std::runtime_error("no free port");
  }
  close(fd);
  return ntohs(addr.sin_port);
}

// True when something accepts connections on the port and answers PING.
bool answers(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(uint16_t(port));
  bool ok = connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
  if (ok) {
    const char ping[] = "PING\r\n";
    char buffer[16] = {};
    ok = write(fd, ping, sizeof ping - 1) == ssize_t(sizeof ping - 1) &&
         read(fd, buffer, sizeof buffer) > 0 && std::string(buffer).starts_with("+PONG");
  }
  close(fd);
  return ok;
}

}  // namespace

std::optional<std::filesystem::path> redis_server_binary() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/usr/sbin"}) {
    const std::filesystem::path path = std::filesystem::path(dir) / "redis-server";
    if (access(path.c_str(), X_OK) == 0) return path;
  }
  return std::nullopt;
}

RedisProcess::RedisProcess() : port_(free_port()) {
  start();
}

RedisProcess::~RedisProcess() {
  stop();
}

void RedisProcess::start() {
  const auto binary = redis_server_binary();
  if (!binary) throw std::runtime_error("redis-server is not installed");
  const std::string log = (dir_.path() / "redis.log").string();
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  pid_ = start_process({binary->string(), "--port", std::to_string(port_), "--bind", "127.0.0.1", "--dir",
                        dir_.path().string(), "--appendonly", "yes", "--save", "", "--daemonize", "no"},
                       fd, fd);
  close(fd);
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (!answers(port_)) {
    if (std::chrono::steady_clock::now() > deadline) throw std::runtime_error("redis-server did not start");
    std::this_thread::sleep_for(20ms);
  }
}

void RedisProcess::restart_empty() {
  kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
  for (const auto& entry : std::filesystem::directory_iterator(dir_.path()))
    if (entry.path().filename() != "redis.log") std::filesystem::remove_all(entry.path());
  start();
}

void RedisProcess::stop() {
  if (pid_ < 0) return;
  kill(pid_, SIGTERM);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

}  // namespace lp::test

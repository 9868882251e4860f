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
#include <fstream>
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

// True when something accepts connections on the port and answers PING (with PONG, or an error when it
// wants a password); with TLS, when it accepts connections.
bool answers(int port, bool tls) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(uint16_t(port));
  bool ok = connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
  if (ok && !tls) {
    const char ping[] = "PING\r\n";
    char buffer[16] = {};
    ok = write(fd, ping, sizeof ping - 1) == ssize_t(sizeof ping - 1) &&
         read(fd, buffer, sizeof buffer) > 0 &&
         (std::string(buffer).starts_with("+PONG") || std::string(buffer).starts_with("-NOAUTH"));
  }
  close(fd);
  return ok;
}

void run(const std::string& command) {
  if (std::system((command + " 2>/dev/null >/dev/null").c_str()) != 0)
    throw std::runtime_error("failed: " + command);
}

}  // namespace

TlsFiles make_tls_files(const std::filesystem::path& dir) {
  const std::string d = dir.string();
  TlsFiles files{dir / "ca.crt", dir / "server.crt", dir / "server.key"};
  run("openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=lightprobe-test-ca -keyout " + d +
      "/ca.key -out " + files.ca_cert.string());
  run("openssl req -newkey rsa:2048 -nodes -subj /CN=localhost -keyout " + files.server_key.string() +
      " -out " + d + "/server.csr");
  std::ofstream(dir / "server.ext") << "subjectAltName=IP:127.0.0.1,DNS:localhost\n";
  run("openssl x509 -req -days 2 -in " + d + "/server.csr -CA " + files.ca_cert.string() + " -CAkey " + d +
      "/ca.key -CAcreateserial -extfile " + d + "/server.ext -out " + files.server_cert.string());
  return files;
}

std::optional<std::filesystem::path> redis_server_binary() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/usr/sbin"}) {
    const std::filesystem::path path = std::filesystem::path(dir) / "redis-server";
    if (access(path.c_str(), X_OK) == 0) return path;
  }
  return std::nullopt;
}

RedisProcess::RedisProcess(RedisSetup setup) : setup_(std::move(setup)), port_(free_port()) {
  if (setup_.tls) {
    std::filesystem::create_directory(dir_.path() / "tls");
    tls_ = make_tls_files(dir_.path() / "tls");
  }
  start();
}

std::string RedisProcess::log() const {
  std::ifstream in(dir_.path() / "redis.log");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

RedisProcess::~RedisProcess() {
  stop();
}

void RedisProcess::start() {
  const auto binary = redis_server_binary();
  if (!binary) throw std::runtime_error("redis-server is not installed");
  const std::string log = (dir_.path() / "redis.log").string();
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  std::vector<std::string> argv = {
      binary->string(), "--bind", "127.0.0.1",   "--dir", dir_.path().string(), "--appendonly", "yes",
      "--save",         "",       "--daemonize", "no"};
  const std::vector<std::string> port = setup_.tls
                                            ? std::vector<std::string>{"--port",
                                                                       "0",
                                                                       "--tls-port",
                                                                       std::to_string(port_),
                                                                       "--tls-cert-file",
                                                                       tls_.server_cert.string(),
                                                                       "--tls-key-file",
                                                                       tls_.server_key.string(),
                                                                       "--tls-ca-cert-file",
                                                                       tls_.ca_cert.string(),
                                                                       "--tls-auth-clients",
                                                                       "no"}
                                            : std::vector<std::string>{"--port", std::to_string(port_)};
  argv.insert(argv.end(), port.begin(), port.end());
  argv.insert(argv.end(), setup_.args.begin(), setup_.args.end());
  pid_ = start_process(argv, fd, fd);
  close(fd);
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (!answers(port_, setup_.tls)) {
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
    if (entry.path().filename() != "redis.log" && entry.path().filename() != "tls")
      std::filesystem::remove_all(entry.path());
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

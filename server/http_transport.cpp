#include "server/http_transport.hpp"

#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "server/raw_response.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;

// How long a connection closed after an error answer keeps reading (and dropping) what the client still
// sends, so that the client reads the answer instead of a connection reset.
constexpr auto kLinger = 1000ms;

thread_local const ConnectionStream* current_stream = nullptr;

// Every connection is a file descriptor: lets the process open as many as the limit allows.
void raise_open_file_limit(int connections) {
  rlimit limit{};
  const rlim_t wanted = rlim_t(connections) + 256;
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur >= wanted) return;
  limit.rlim_cur = std::min(wanted, limit.rlim_max);
  setrlimit(RLIMIT_NOFILE, &limit);
  if (limit.rlim_cur < wanted)
    spdlog::warn("open files are limited to {}: fewer than --max-connections connections may be served",
                 limit.rlim_cur);
}

int listen_on(const addrinfo& ai) {
  const int fd = socket(ai.ai_family, ai.ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, ai.ai_protocol);
  if (fd < 0) return -1;
  const int one = 1;  // SO_REUSEADDR only: a port left in TIME_WAIT can be bound, a served port cannot
  if (setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) == 0 &&
      ::bind(fd, ai.ai_addr, ai.ai_addrlen) == 0 && listen(fd, SOMAXCONN) == 0)
    return fd;
  const int error = errno;
  close(fd);
  errno = error;
  return -1;
}

// Answers a connection that is not served, without a thread: what the client sent so far is dropped
// first, so that closing does not reset the connection before the answer is read.
void refuse(int fd, const std::string& response) {
  char drop[16 * 1024];
  while (recv(fd, drop, sizeof drop, MSG_DONTWAIT) > 0) {
  }
  [[maybe_unused]] const ssize_t sent =
      send(fd, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  shutdown(fd, SHUT_WR);
  close(fd);
}

void answer_and_close(ConnectionStream& stream, const HeadError& error) {
  std::string ip;
  int port = 0;
  stream.get_remote_ip_and_port(ip, port);
  spdlog::debug("{}:{} answered {} {}: {}", ip, port, api::http_status(error.code),
                api::code_name(error.code), error.message);
  if (stream.write_all(raw_error_response(error.code, error.message))) stream.close_gracefully(kLinger);
}

}  // namespace

bool request_body_over_limit() {
  return current_stream && current_stream->body_over_limit();
}

HttpTransport::HttpTransport(TransportLimits limits)
    : limits_(limits), stop_fd_(eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  if (stop_fd_ < 0) throw std::runtime_error(std::string("eventfd: ") + std::strerror(errno));
  set_payload_max_length(size_t(limits.max_body));
  set_keep_alive_timeout(limits.keep_alive_timeout.count());
}

HttpTransport::~HttpTransport() {
  if (listen_fd_ >= 0) close(listen_fd_);
  close(stop_fd_);
}

int HttpTransport::bind(const std::string& host, int port) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string where = fmt::format("cannot listen on {}:{}", host, port);
  if (const int error = getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found))
    throw std::runtime_error(where + ": " + gai_strerror(error));
  int error = 0;
  for (const addrinfo* ai = found; ai && listen_fd_ < 0; ai = ai->ai_next)
    if ((listen_fd_ = listen_on(*ai)) < 0) error = errno;
  freeaddrinfo(found);
  if (listen_fd_ < 0) throw std::runtime_error(where + ": " + std::strerror(error));
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  std::string ip;
  socket_address(addr, ip, port);
  svr_sock_ = listen_fd_;  // httplib ends chunked responses (event streams) once this is INVALID_SOCKET
  raise_open_file_limit(limits_.max_connections);
  return port;
}

void HttpTransport::run() {
  accept_connections();
  std::unique_lock lock(mutex_);
  ended_.wait(lock, [this] { return closing_ && connections_.empty(); });
}

void HttpTransport::accept_connections() {
  pollfd fds[2] = {{listen_fd_, POLLIN, 0}, {stop_fd_, POLLIN, 0}};
  while (!stopping_) {
    if (poll(fds, 2, -1) < 0 && errno != EINTR) break;
    if (fds[1].revents & POLLIN) break;
    sockaddr_storage addr{};
    socklen_t len = sizeof addr;
    const int fd =
        accept4(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
      if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM)
        std::this_thread::sleep_for(10ms);
      continue;
    }
    std::string ip;
    int port = 0;
    socket_address(addr, ip, port);
    admit(fd, ip, port);
  }
  std::lock_guard lock(mutex_);
  close(listen_fd_);
  listen_fd_ = -1;
}

void HttpTransport::admit(int fd, const std::string& ip, int port) {
  std::string refusal;
  {
    std::lock_guard lock(mutex_);
    if (int(connections_.size()) >= limits_.max_connections)
      refusal =
          fmt::format("{} connections are open, the server's limit (--max-connections)", connections_.size());
    else if (per_client_[ip] >= limits_.max_connections_per_client)
      refusal =
          fmt::format("{} connections from {} are open, the limit per client (--max-connections-per-client)",
                      per_client_[ip], ip);
    if (refusal.empty()) {
      connections_.insert(fd);
      ++per_client_[ip];
    } else if (per_client_[ip] == 0) {
      per_client_.erase(ip);
    }
  }
  if (!refusal.empty()) {
    spdlog::debug("{}:{} refused: {}", ip, port, refusal);
    return refuse(fd, raw_error_response(api::ErrorCode::TooManyConnections, refusal, "Retry-After: 1\r\n"));
  }
  const int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  try {
    std::thread([this, fd, ip, port] {
      serve(fd, ip, port);
      release(fd, ip);
    }).detach();
  } catch (const std::system_error& e) {
    spdlog::error("no thread for a connection from {}: {}", ip, e.what());
    release(fd, ip);
  }
}

void HttpTransport::release(int fd, const std::string& ip) {
  std::lock_guard lock(mutex_);
  connections_.erase(fd);
  if (--per_client_[ip] <= 0) per_client_.erase(ip);
  close(fd);  // under the lock, so close_connections() never shuts down a reused descriptor
  ended_.notify_all();
}

void HttpTransport::serve(int fd, const std::string& ip, int port) {
  ConnectionStream stream(fd, stop_fd_, ip, port, limits_.io_timeout);
  current_stream = &stream;
  auto start = std::chrono::steady_clock::now();  // the first request's head is timed from the accept
  for (size_t served = 0;; ++served) {
    RequestHead head;
    if (!wait_for_request(stream, served == 0) || !read_head(stream, start, head)) break;
    stream.begin_request(std::move(head.text), head.body);
    const bool close = stopping_ || served + 1 >= keep_alive_max_count_;
    bool closed = false;
    const bool answered = process_request(stream, close, closed, {}) && stream.flush();
    if (!answered || close || closed || !stream.body_finished()) {
      stream.close_gracefully(kLinger);
      break;
    }
    start = std::chrono::steady_clock::now();
  }
  current_stream = nullptr;
}

// Waits for the first byte of the next request (the blank lines some clients send between requests
// are skipped); false when the client closes, stays idle too long, or the transport stops.
bool HttpTransport::wait_for_request(ConnectionStream& stream, bool first) {
  const auto deadline =
      std::chrono::steady_clock::now() + (first ? limits_.header_timeout : limits_.keep_alive_timeout);
  for (;;) {
    const auto input = stream.input();
    const size_t blank = std::min(input.find_first_not_of("\r\n"), input.size());
    stream.consume(blank);
    if (!stream.input().empty()) return true;
    if (stopping_ || stream.fill(deadline, true) != ConnectionStream::Fill::Data) return false;
  }
}

bool HttpTransport::read_head(ConnectionStream& stream, std::chrono::steady_clock::time_point start,
                              RequestHead& head) {
  HeadScanner scanner;
  const auto deadline = start + limits_.header_timeout;
  for (;;) {
    switch (scanner.scan(stream.input())) {
      case HeadScanner::State::Error:
        answer_and_close(stream, scanner.error());
        return false;
      case HeadScanner::State::Complete: {
        auto checked = check_request_head(stream.input().substr(0, scanner.head_length()), limits_.max_body);
        stream.consume(scanner.head_length());
        if (!checked.head) {
          answer_and_close(stream, checked.error);
          return false;
        }
        head = std::move(*checked.head);
        return true;
      }
      case HeadScanner::State::NeedMore:
        break;
    }
    switch (stream.fill(deadline, false)) {
      case ConnectionStream::Fill::Data:
        break;
      case ConnectionStream::Fill::TimedOut:
        answer_and_close(stream,
                         {api::ErrorCode::RequestTimeout,
                          fmt::format("the request head did not arrive within {} s (--header-timeout-s)",
                                      limits_.header_timeout.count())});
        return false;
      default:
        return false;
    }
  }
}

void HttpTransport::stop_accepting() {
  stopping_ = true;
  const uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = write(stop_fd_, &one, sizeof one);
}

void HttpTransport::close_connections() {
  stop_accepting();
  std::lock_guard lock(mutex_);
  closing_ = true;
  svr_sock_ = INVALID_SOCKET;
  for (const int fd : connections_) shutdown(fd, SHUT_RDWR);
  ended_.notify_all();
}

}  // namespace lp::server

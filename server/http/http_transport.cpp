#include "server/http/http_transport.hpp"

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

#include "server/http/raw_response.hpp"
#include "server/http/request_context.hpp"

namespace lp::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// How long a connection closed after an error answer keeps reading (and dropping) what the client still
// sends, so that the client reads the answer instead of a connection reset.
constexpr auto kLinger = 1000ms;
// HTTP workers waiting for ready connections, per core: two, so that a core has a request to work on while
// the other worker of that core is in a system call (measured: one per core answers fewer requests).
constexpr int kWorkersPerCore = 2;
// How long every HTTP worker may be held by its request before another worker is started.
constexpr auto kPatience = 5ms;
// How often parked connections are checked for having waited too long.
constexpr auto kSweepInterval = 100ms;

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

// The last bytes sent on a connection that is ended without a worker: what the client sent so far is
// dropped first, so that closing does not reset the connection before the answer is read.
void say_last_words(int fd, const std::string& response) {
  char drop[16 * 1024];
  while (recv(fd, drop, sizeof drop, MSG_DONTWAIT) > 0) {
  }
  [[maybe_unused]] const ssize_t sent =
      send(fd, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  shutdown(fd, SHUT_WR);
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
    : limits_(limits),
      connections_(limits.max_connections, limits.max_connections_per_client, limits.io_timeout),
      stop_fd_(eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
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
  const int workers = kWorkersPerCore * std::max(1, int(std::thread::hardware_concurrency()));
  ElasticWorkers pool(
      workers, kPatience, [this] { return connections_.wait_ready(); }, [this](uint64_t id) { serve(id); });
  accept_connections();
  connections_.close_idle();
  {
    std::unique_lock lock(mutex_);
    closed_.wait(lock, [this] { return closing_; });
  }
  connections_.wait_until_empty();
  connections_.end_waits();
}

// Accepts connections, and ends those parked too long, until stop_accepting().
void HttpTransport::accept_connections() {
  pollfd fds[2] = {{listen_fd_, POLLIN, 0}, {stop_fd_, POLLIN, 0}};
  auto last_sweep = Clock::now();
  while (!stopping_) {
    const int ready = poll(fds, 2, int(kSweepInterval.count()));
    if (ready < 0 && errno != EINTR) break;
    if (fds[1].revents & POLLIN) break;
    if (const auto now = Clock::now(); now - last_sweep >= kSweepInterval) {
      connections_.expire(now, [this](Connection& c) { time_out(c); });
      last_sweep = now;
    }
    if (ready <= 0 || !(fds[0].revents & POLLIN)) continue;
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
  const int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  const bool proxy = limits_.trusted_proxies.contains(ip);
  const auto refusal = connections_.admit(fd, ip, port, proxy, Clock::now() + limits_.header_timeout);
  if (!refusal) return;
  spdlog::debug("{}:{} refused: {}", ip, port, *refusal);
  say_last_words(fd, raw_error_response(api::ErrorCode::TooManyConnections, *refusal, "Retry-After: 1\r\n"));
  close(fd);
}

// A parked connection that waited too long: a request head that did not arrive in time is answered 408;
// a connection that never sent a request, or stayed idle between requests, is just closed.
void HttpTransport::time_out(Connection& c) const {
  if (c.stream.input().empty()) return;
  spdlog::debug("{}:{} answered 408: the request head was not complete in time", c.ip, c.port);
  say_last_words(c.fd, raw_error_response(api::ErrorCode::RequestTimeout,
                                          fmt::format("the request head did not arrive within {} s "
                                                      "(--header-timeout-s)",
                                                      limits_.header_timeout.count())));
}

void HttpTransport::serve(uint64_t id) {
  Connection* c = connections_.take(id);
  if (!c) return;
  if (serve_requests(*c))
    connections_.park(*c, parked_deadline(*c));
  else
    connections_.release(*c);
}

// A request begun (a head arriving, or the first request of a connection) must be complete within the
// header timeout from its start; an idle connection is kept for the keep-alive timeout.
Clock::time_point HttpTransport::parked_deadline(const Connection& c) const {
  return c.started ? *c.started + limits_.header_timeout : Clock::now() + limits_.keep_alive_timeout;
}

// Answers the requests whose bytes have arrived, in order; true if the connection stays open, to wait
// for more bytes without a thread.
bool HttpTransport::serve_requests(Connection& c) {
  current_stream = &c.stream;
  const size_t served_before = c.served;
  bool open = false;
  for (;;) {
    const Next next = next_request(c, c.served == served_before);
    if (next != Next::Request) {
      open = next == Next::Idle;
      break;
    }
    RequestHead head;
    const Head got = read_head(c, head);
    if (got != Head::Complete) {
      open = got == Head::Incomplete;
      break;
    }
    std::string client = c.proxy ? limits_.trusted_proxies.client_of(c.ip, head.forwarded_for) : c.ip;
    if (c.proxy) {
      if (const auto refusal = connections_.begin_request(client)) {
        answer_and_close(c.stream, {api::ErrorCode::TooManyConnections, *refusal});
        break;
      }
    }
    c.stream.begin_request(std::move(head.text), head.body);
    begin_request_context(std::move(head.accept_encoding), client);
    const bool close = stopping_ || c.served + 1 >= keep_alive_max_count_;
    bool closed = false;
    const bool answered = process_request(c.stream, close, closed, {}) && c.stream.flush();
    end_request_context();
    if (c.proxy) connections_.end_request(client);
    ++c.served;
    c.started.reset();
    if (!answered || close || closed || !c.stream.body_finished()) {
      c.stream.close_gracefully(kLinger);
      break;
    }
  }
  current_stream = nullptr;
  return open;
}

// Whether bytes of a request are at hand; the blank lines some clients send between requests are
// skipped. When the connection has just become ready, what the socket has is read (without waiting);
// after a response, only what was already read counts (pipelined requests): a connection whose next
// request arrives later waits behind the connections that were ready before it.
HttpTransport::Next HttpTransport::next_request(Connection& c, bool read) {
  for (;;) {
    const auto input = c.stream.input();
    c.stream.consume(std::min(input.find_first_not_of("\r\n"), input.size()));
    if (!c.stream.input().empty()) {
      if (!c.started) c.started = Clock::now();
      return Next::Request;
    }
    if (!read) return Next::Idle;
    switch (c.stream.fill(Clock::time_point{})) {
      case ConnectionStream::Fill::Data:
        continue;
      case ConnectionStream::Fill::TimedOut:
        return Next::Idle;
      default:
        return Next::Gone;
    }
  }
}

// Reads the head as far as it has arrived; an incomplete head is resumed when more bytes arrive.
HttpTransport::Head HttpTransport::read_head(Connection& c, RequestHead& head) {
  for (;;) {
    switch (c.head.scan(c.stream.input())) {
      case HeadScanner::State::Error:
        answer_and_close(c.stream, c.head.error());
        return Head::Failed;
      case HeadScanner::State::Complete: {
        const size_t length = c.head.head_length();
        c.head = HeadScanner{};
        auto checked = check_request_head(c.stream.input().substr(0, length), limits_.max_body);
        c.stream.consume(length);
        if (!checked.head) {
          answer_and_close(c.stream, checked.error);
          return Head::Failed;
        }
        head = std::move(*checked.head);
        return Head::Complete;
      }
      case HeadScanner::State::NeedMore:
        break;
    }
    switch (c.stream.fill(Clock::time_point{})) {
      case ConnectionStream::Fill::Data:
        break;
      case ConnectionStream::Fill::TimedOut:
        return Head::Incomplete;
      default:
        return Head::Failed;
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
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  closed_.notify_all();
  svr_sock_ = INVALID_SOCKET;
  connections_.shut_down_all();
}

}  // namespace lp::server

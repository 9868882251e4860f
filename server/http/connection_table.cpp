#include "server/http/connection_table.hpp"

#include <fmt/format.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace lp::server {

using Clock = std::chrono::steady_clock;

Connection::Connection(uint64_t id_, int fd_, std::string ip_, int port_, bool proxy_,
                       std::chrono::seconds io_timeout)
    : id(id_), fd(fd_), ip(std::move(ip_)), port(port_), proxy(proxy_), stream(fd_, ip, port_, io_timeout) {}

ConnectionTable::ConnectionTable(int max_connections, int max_per_client, std::chrono::seconds io_timeout)
    : max_connections_(max_connections),
      max_per_client_(max_per_client),
      io_timeout_(io_timeout),
      epoll_fd_(epoll_create1(EPOLL_CLOEXEC)),
      end_fd_(eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  epoll_event ev{};
  ev.events = EPOLLIN;  // level-triggered: once ended, every waiter wakes
  ev.data.u64 = 0;
  if (epoll_fd_ < 0 || end_fd_ < 0 || epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, end_fd_, &ev) != 0)
    throw std::runtime_error(std::string("epoll: ") + std::strerror(errno));
}

ConnectionTable::~ConnectionTable() {
  for (auto& [id, c] : connections_) close(c->fd);
  close(end_fd_);
  close(epoll_fd_);
}

std::optional<std::string> ConnectionTable::admit(int fd, const std::string& ip, int port, bool proxy,
                                                  Clock::time_point deadline) {
  std::lock_guard lock(mutex_);
  if (int(connections_.size()) >= max_connections_)
    return fmt::format("{} connections are open, the server's limit (--max-connections)",
                       connections_.size());
  const int from_client = proxy ? 0 : per_client_[ip];
  if (from_client >= max_per_client_)
    return fmt::format("{} connections from {} are open, the limit per client (--max-connections-per-client)",
                       from_client, ip);
  auto c = std::make_unique<Connection>(next_id_++, fd, ip, port, proxy, io_timeout_);
  c->started = Clock::now();
  c->deadline = deadline;
  c->parked = true;
  if (!arm(*c, EPOLL_CTL_ADD)) {
    if (!proxy && from_client == 0) per_client_.erase(ip);
    return std::string("the connection cannot be watched: ") + std::strerror(errno);
  }
  if (!proxy) ++per_client_[ip];
  connections_.emplace(c->id, std::move(c));
  return std::nullopt;
}

bool ConnectionTable::arm(Connection& c, int operation) {
  epoll_event ev{};
  ev.events = EPOLLIN | EPOLLRDHUP | EPOLLONESHOT;
  ev.data.u64 = c.id;
  return epoll_ctl(epoll_fd_, operation, c.fd, &ev) == 0;
}

std::optional<uint64_t> ConnectionTable::wait_ready() {
  for (;;) {
    epoll_event ev{};
    const int n = epoll_wait(epoll_fd_, &ev, 1, -1);
    if (n < 0 && errno != EINTR) return std::nullopt;
    if (n <= 0) continue;
    const uint64_t id = ev.data.u64;
    if (id == 0) return std::nullopt;
    return id;
  }
}

Connection* ConnectionTable::take(uint64_t id) {
  std::lock_guard lock(mutex_);
  const auto it = connections_.find(id);
  if (it == connections_.end() || !it->second->parked) return nullptr;
  it->second->parked = false;
  return it->second.get();
}

void ConnectionTable::park(Connection& c, Clock::time_point deadline) {
  std::lock_guard lock(mutex_);
  c.deadline = deadline;
  c.parked = true;
  if (closing_idle_ || !arm(c, EPOLL_CTL_MOD)) end(connections_.find(c.id));
}

std::optional<std::string> ConnectionTable::begin_request(const std::string& client) {
  std::lock_guard lock(mutex_);
  int& in_flight = proxied_requests_[client];
  if (in_flight >= max_per_client_)
    return fmt::format(
        "{} requests from {} are in flight, the limit per client (--max-connections-per-client)", in_flight,
        client);
  ++in_flight;
  return std::nullopt;
}

void ConnectionTable::end_request(const std::string& client) {
  std::lock_guard lock(mutex_);
  if (--proxied_requests_[client] <= 0) proxied_requests_.erase(client);
}

void ConnectionTable::release(Connection& c) {
  std::lock_guard lock(mutex_);
  end(connections_.find(c.id));
}

// Called with the mutex held. The descriptor is closed under the lock, so shut_down_all() never shuts
// down a reused one.
void ConnectionTable::end(std::unordered_map<uint64_t, std::unique_ptr<Connection>>::iterator it) {
  const std::unique_ptr<Connection> c = std::move(it->second);
  connections_.erase(it);
  if (!c->proxy && --per_client_[c->ip] <= 0) per_client_.erase(c->ip);
  close(c->fd);
  if (connections_.empty()) emptied_.notify_all();
}

void ConnectionTable::expire(Clock::time_point now, const std::function<void(Connection&)>& last_words) {
  std::lock_guard lock(mutex_);
  for (auto it = connections_.begin(); it != connections_.end();) {
    const auto next = std::next(it);
    if (it->second->parked && it->second->deadline <= now) {
      last_words(*it->second);
      end(it);
    }
    it = next;
  }
}

void ConnectionTable::close_idle() {
  std::lock_guard lock(mutex_);
  closing_idle_ = true;
  for (auto it = connections_.begin(); it != connections_.end();) {
    const auto next = std::next(it);
    if (it->second->parked) end(it);
    it = next;
  }
}

void ConnectionTable::shut_down_all() {
  std::lock_guard lock(mutex_);
  for (const auto& [id, c] : connections_) shutdown(c->fd, SHUT_RDWR);
}

void ConnectionTable::wait_until_empty() {
  std::unique_lock lock(mutex_);
  emptied_.wait(lock, [this] { return connections_.empty(); });
}

void ConnectionTable::end_waits() {
  const uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = write(end_fd_, &one, sizeof one);
}

size_t ConnectionTable::size() const {
  std::lock_guard lock(mutex_);
  return connections_.size();
}

}  // namespace lp::server

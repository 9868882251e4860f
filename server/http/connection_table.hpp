#pragma once
// The open client connections. Between requests (and while a request head is still arriving) a
// connection is parked in an epoll set, holding no thread; when its next bytes arrive it is handed to
// exactly one worker (EPOLLONESHOT), which parks it again or releases it. Parked connections that wait
// past their deadline are ended by expire(). Connections are counted in total and per client address.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "server/http/connection_stream.hpp"
#include "server/http/request_head.hpp"

namespace lp::server {

struct Connection {
  Connection(uint64_t id, int fd, std::string ip, int port, bool proxy, std::chrono::seconds io_timeout);
  const uint64_t id;
  const int fd;
  const std::string ip;
  const int port;
  const bool proxy;  // from a trusted proxy: its requests are counted per client, not the connection
  ConnectionStream stream;
  HeadScanner head;  // the head of the request being read
  std::optional<std::chrono::steady_clock::time_point>
      started;                                     // when its first byte arrived (the accept, for the first)
  size_t served = 0;                               // requests answered
  std::chrono::steady_clock::time_point deadline;  // while parked
  bool parked = false;
};

class ConnectionTable {
 public:
  ConnectionTable(int max_connections, int max_per_client, std::chrono::seconds io_timeout);
  ~ConnectionTable();
  ConnectionTable(const ConnectionTable&) = delete;
  ConnectionTable& operator=(const ConnectionTable&) = delete;

  // Takes `fd` and parks it until `deadline`; or returns why it is refused (over a limit), and then the
  // caller still owns `fd`. A `proxy`'s connection counts towards the total only.
  std::optional<std::string> admit(int fd, const std::string& ip, int port, bool proxy,
                                   std::chrono::steady_clock::time_point deadline);
  // Counts a request a proxy forwards from `client`, or returns why it is refused (as many requests of
  // that client in flight as a client may hold connections); end_request() when it is answered.
  std::optional<std::string> begin_request(const std::string& client);
  void end_request(const std::string& client);

  // Blocks until a parked connection has bytes (its id) or end_waits() was called (std::nullopt).
  std::optional<uint64_t> wait_ready();
  // The ready connection of this id, now owned by the calling worker; nullptr if it has been ended.
  Connection* take(uint64_t id);
  // Gives the connection back to wait for more bytes until `deadline`; ends it instead when idle
  // connections are being closed (close_idle()).
  void park(Connection& c, std::chrono::steady_clock::time_point deadline);
  // Closes and forgets a connection a worker owns.
  void release(Connection& c);

  // Ends every parked connection whose deadline has passed, after calling `last_words` on it (which must
  // not block).
  void expire(std::chrono::steady_clock::time_point now, const std::function<void(Connection&)>& last_words);
  // Ends every parked connection, and from now on every connection given back to park().
  void close_idle();
  // Shuts down every connection's socket, so that no read or write on them waits any longer.
  void shut_down_all();
  // Blocks until no connection is open.
  void wait_until_empty();
  // Makes every present and future wait_ready() return std::nullopt.
  void end_waits();

  size_t size() const;

 private:
  void end(std::unordered_map<uint64_t, std::unique_ptr<Connection>>::iterator it);
  bool arm(Connection& c, int operation);

  const int max_connections_;
  const int max_per_client_;
  const std::chrono::seconds io_timeout_;
  int epoll_fd_ = -1;
  int end_fd_ = -1;  // an eventfd in the epoll set, readable once end_waits() is called
  mutable std::mutex mutex_;
  std::condition_variable emptied_;
  uint64_t next_id_ = 1;  // 0 is the end_fd_'s entry
  bool closing_idle_ = false;
  std::unordered_map<uint64_t, std::unique_ptr<Connection>> connections_;
  std::unordered_map<std::string, int> per_client_;        // direct connections by address
  std::unordered_map<std::string, int> proxied_requests_;  // requests in flight by forwarded client
};

}  // namespace lp::server

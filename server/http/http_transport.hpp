#pragma once
// The HTTP transport under httplib's routing. httplib::Server keeps the routes, handlers and request
// parsing (process_request); this class owns the sockets:
//  - the listening socket, bound without SO_REUSEPORT, so a second server on a served port fails to bind;
//  - connections parked in epoll between requests and while their head arrives (connection_table.hpp),
//    served by a pool of about as many threads as cores that grows while its threads are held by slow
//    clients, event streams or long work (elastic_workers.hpp): idle and slow clients hold no thread, and
//    under load few threads compete for the cores, so requests are answered in arrival order;
//    connections are capped in total and per client address (503 and Connection: close);
//  - TCP_NODELAY on every connection, so small keep-alive responses are not held back by Nagle's algorithm;
//  - each request's head read within --header-timeout-s and size limits (408, 414, 431) and checked
//    before its body (request_head.hpp); bodies framed and bounded by --max-upload-mb
//    (connection_stream.hpp);
//  - idle keep-alive connections closed after --keep-alive-timeout-s; pipelined requests answered in order.
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "server/http/connection_table.hpp"
#include "server/http/elastic_workers.hpp"
#include "server/http/transport_limits.hpp"

namespace lp::server {

class HttpTransport : public httplib::Server {
 public:
  explicit HttpTransport(TransportLimits limits);
  ~HttpTransport() override;
  HttpTransport(const HttpTransport&) = delete;
  HttpTransport& operator=(const HttpTransport&) = delete;

  // Binds host:port (port 0: any free port) and listens; returns the port. Throws std::runtime_error.
  int bind(const std::string& host, int port);
  // Accepts and serves connections; returns after close_connections(), once every connection has ended.
  void run();

  // Stopping, in two steps, each safe from any thread:
  // closes the listening socket (new connections are refused) and the idle keep-alive connections;
  // requests being read or answered go on, and their connections close after the response.
  void stop_accepting();
  // Ends every connection at once, event streams and slow readers or writers included: their sockets are
  // shut down, so no read or write waits any longer, and run() returns when their requests are done.
  void close_connections();

 private:
  enum class Next { Request, Idle, Gone };
  enum class Head { Complete, Incomplete, Failed };
  void accept_connections();
  void admit(int fd, const std::string& ip, int port);
  void serve(uint64_t id);
  bool serve_requests(Connection& c);
  Next next_request(Connection& c, bool read);
  Head read_head(Connection& c, RequestHead& head);
  std::chrono::steady_clock::time_point parked_deadline(const Connection& c) const;
  void time_out(Connection& c) const;

  TransportLimits limits_;
  ConnectionTable connections_;
  int listen_fd_ = -1;
  int stop_fd_ = -1;  // an eventfd, readable once stop_accepting() is called
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable closed_;
  bool closing_ = false;
};

// Whether the body of the request being handled on this thread went over its limit. A chunked body is
// known to be too large only while it is read; its reader then fails, and the handler should answer 413.
bool request_body_over_limit();

}  // namespace lp::server

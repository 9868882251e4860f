#pragma once
// The HTTP server: routes, limits, request logging, graceful stop.
#include <httplib.h>

#include <atomic>
#include <filesystem>
#include <memory>

#include "server/app.hpp"
#include "server/http/bearer_auth.hpp"
#include "server/http/browser_policy.hpp"
#include "server/http/http_transport.hpp"
#include "server/http/router.hpp"
#include "server/observability/access_log.hpp"

namespace lp::server {

class Server {
 public:
  explicit Server(App& app);

  // Binds (port 0 = any free port) and returns the port; throws std::runtime_error if it cannot.
  int bind();
  void run();  // blocks until close_connections() (and the connections it closes) are done

  // Stopping, in two steps (the sequence is in shutdown.hpp); both are safe from any thread.
  // New connections are refused and idle ones closed; a request that arrives on an open connection gets
  // 503 "shutting_down" (connection closed); requests in flight go on.
  void stop_accepting();
  // Closes every connection at once (http/http_transport.hpp); run() returns once their threads are done.
  void close_connections();

  const Router& router() const { return router_; }

 private:
  void mount_web_dir(const std::filesystem::path& dir);
  // What is answered before the routes, in order: a stop in progress, the browser policy (and CORS
  // preflights), a missing token, a start still loading. True if `res` is the answer.
  bool answer_before_routing(const httplib::Request& req, httplib::Response& res);

  App& app_;
  HttpTransport http_;
  Router router_;
  AccessLog access_log_;
  BrowserPolicy browser_;
  BearerAuth auth_;
  std::atomic<bool> accepting_{true};
};

}  // namespace lp::server

#pragma once
// The HTTP server: routes, limits, request logging, graceful stop.
#include <filesystem>
#include <memory>

#include <httplib.h>

#include "server/app.hpp"
#include "server/router.hpp"

namespace lp::server {

class Server {
 public:
  explicit Server(App& app);

  // Binds (port 0 = any free port) and returns the port; throws std::runtime_error if it cannot.
  int bind();
  void run();   // blocks until stop()
  void stop();  // safe from a signal-watching thread

  const Router& router() const { return router_; }

 private:
  void mount_web_dir(const std::filesystem::path& dir);

  App& app_;
  httplib::Server http_;
  Router router_;
};

}  // namespace lp::server

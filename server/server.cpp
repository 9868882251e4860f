#include "server/server.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "server/method_policy.hpp"
#include "server/routes.hpp"

namespace lp::server {
namespace {

// Worker threads for connections; computation itself runs on oneTBB's pool.
size_t http_worker_count(const Options& options) {
  const int cores = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  return size_t(std::max(16, 4 * cores));
}

}  // namespace

Server::Server(App& app) : app_(app), router_(http_), access_log_(app.options.access_log_sample) {
  http_.new_task_queue = [n = http_worker_count(app.options)] { return new httplib::ThreadPool(n); };
  http_.set_payload_max_length(size_t(app.options.max_upload_mb) * 1024 * 1024);
  http_.set_read_timeout(60);
  http_.set_write_timeout(60);
  http_.set_keep_alive_max_count(1000);

  http_.set_pre_routing_handler([this](const httplib::Request&, httplib::Response& res) {
    AccessLog::start_request();
    if (accepting_.load()) return httplib::Server::HandlerResponse::Unhandled;
    res.set_header("Connection", "close");
    send_error(res, 503, "shutting_down", "the server is shutting down");
    return httplib::Server::HandlerResponse::Handled;
  });
  http_.set_logger(
      [this](const httplib::Request& req, const httplib::Response& res) { access_log_.record(req, res); });
  // Responses httplib makes itself (no route, body too large, ...) get the JSON error shape too.
  http_.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    if ((res.status == 404 || res.status == 400) && refuse_method(router_, req, res)) return;
    if (res.status == 404) send_error(res, 404, "not_found", "no endpoint " + req.method + " " + req.path);
    else if (res.status == 413) send_error(res, 413, "payload_too_large", "the request body is over the server's limit (--max-upload-mb)");
    else send_error(res, res.status, "bad_request", "the request could not be handled");
  });
  http_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string message = "internal error";
    try {
      if (ep) std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
    send_error(res, 500, "internal", message);
  });

  register_meta_routes(router_, app_);
  register_envmap_routes(router_, app_);
  register_sample_routes(router_, app_);
  register_render_routes(router_, app_);
  register_fresnel_routes(router_, app_);
  register_median_cut_routes(router_, app_);
}

// Static files are looked up before the routes, but web/ holds no api/ folder, so every /api path
// still reaches its route or the JSON 404.
void Server::mount_web_dir(const std::filesystem::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec) || !http_.set_mount_point("/", dir.string(), {{"Cache-Control", "no-cache"}})) {
    spdlog::warn("no dashboard: {} is not a readable directory (serving the API only)", dir.string());
    return;
  }
  spdlog::info("dashboard: serving {} at /", dir.string());
}

int Server::bind() {
  const auto& o = app_.options;
  errno = 0;
  const int port = o.port == 0 ? http_.bind_to_any_port(o.host) : (http_.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port <= 0)
    throw std::runtime_error("cannot listen on " + o.host + ":" + std::to_string(o.port) +
                             (errno ? std::string(": ") + std::strerror(errno) : std::string()));
  mount_web_dir(o.web_dir);  // after the bind, so a port in use gives one message only
  return port;
}

void Server::run() { http_.listen_after_bind(); }

void Server::stop_accepting() { accepting_.store(false); }

void Server::close_connections() { http_.stop(); }

}  // namespace lp::server

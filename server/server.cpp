#include "server/server.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>

#include "server/http/compression.hpp"
#include "server/http/method_policy.hpp"
#include "server/http/probe_routes.hpp"
#include "server/http/request_context.hpp"
#include "server/http/request_id.hpp"
#include "server/routes/routes.hpp"

namespace lp::server {
Server::Server(App& app)
    : app_(app),
      http_(app.options.transport),
      router_(http_),
      access_log_(app.options.log.access_log_sample, app.options.log.format),
      browser_(app.options.host, app.options.browser),
      auth_(app.options.auth_token) {
  http_.set_keep_alive_max_count(1000);

  http_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    return answer_before_routing(req, res) ? httplib::Server::HandlerResponse::Handled
                                           : httplib::Server::HandlerResponse::Unhandled;
  });
  http_.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
    compress_response(current_request().accept_encoding, res);
  });
  http_.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
    const RequestContext& r = current_request();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    app_.http_metrics.record(method_label(req.method), route_label(r.route, req.path, res.status), res.status,
                             seconds);
    access_log_.record(req, res, seconds);
  });
  // Responses httplib makes itself (no route, body too large, ...) get the JSON error shape too.
  http_.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    if ((res.status == 404 || res.status == 400 || res.status == 405) && refuse_method(router_, req, res))
      return;
    if (res.status == 404)
      send_error(res, api::ErrorCode::NotFound, "no endpoint " + req.method + " " + req.path);
    else if (res.status == 413)
      send_error(res, api::ErrorCode::PayloadTooLarge, kBodyTooLargeMessage);
    else if (res.status == 405)
      send_error(res, api::ErrorCode::MethodNotAllowed, "method not allowed");
    else {
      const int status = res.status;  // httplib's own refusal (a bad Range, ...) keeps its status
      send_error(res, api::ErrorCode::BadRequest, "the request could not be handled");
      res.status = status;
    }
  });
  http_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string message = "internal error";
    try {
      if (ep) std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
    send_error(res, api::ErrorCode::Internal, message);
  });

  register_meta_routes(router_, app_);
  register_envmap_routes(router_, app_);
  register_asset_routes(router_, app_);
  register_sample_routes(router_, app_);
  register_render_routes(router_, app_);
  register_turntable_routes(router_, app_);
  register_fresnel_routes(router_, app_);
  register_median_cut_routes(router_, app_);
  register_sh_routes(router_, app_);
  register_brdf_lut_routes(router_, app_);
  register_prefilter_routes(router_, app_);
  register_sun_routes(router_, app_);
  register_metrics_routes(router_, app_);
  register_content_routes(router_, app_);
}

bool Server::answer_before_routing(const httplib::Request& req, httplib::Response& res) {
  current_request().id = request_id_for(req);
  res.set_header(kRequestIdHeader, current_request().id);
  if (!accepting_.load()) {
    res.set_header("Connection", "close");
    send_error(res, api::ErrorCode::ShuttingDown, "the server is shutting down");
    return true;
  }
  if (const auto refusal = browser_.refusal(req)) {
    send_error(res, refusal->code(), refusal->what());
    return true;
  }
  if (browser_.answer_cors(req, res, router_) || auth_.refuse(req, res)) return true;
  if (!app_.ready.load() && is_api_path(req.path) && !is_probe(req.path)) {
    send_not_ready(res);
    return true;
  }
  return false;
}

// Static files are looked up before the routes, but web/ holds no api/ folder, so every /api path
// still reaches its route or the JSON 404.
void Server::mount_web_dir(const std::filesystem::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec) ||
      !http_.set_mount_point("/", dir.string(), {{"Cache-Control", "no-cache"}})) {
    spdlog::warn("no dashboard: {} is not a readable directory (serving the API only)", dir.string());
    return;
  }
  spdlog::info("dashboard: serving {} at /", dir.string());
}

int Server::bind() {
  const int port = http_.bind(app_.options.host, app_.options.port);
  mount_web_dir(app_.options.web_dir);  // after the bind, so a port in use gives one message only
  return port;
}

void Server::run() {
  http_.run();
}

void Server::stop_accepting() {
  accepting_.store(false);
  http_.stop_accepting();
}

void Server::close_connections() {
  http_.close_connections();
}

}  // namespace lp::server

#include "server/http/router.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <regex>

#include "api/api_error.hpp"
#include "api/query_policy.hpp"
#include "engine/core/error.hpp"
#include "server/http/http_transport.hpp"
#include "server/http/memory_refusal.hpp"
#include "server/http/request_context.hpp"
#include "server/http/request_id.hpp"

namespace lp::server {
namespace {

// "/api/v1/envmaps/{id}/image" -> "/api/v1/envmaps/([^/]+)/image" (other characters escaped).
std::string to_regex(const std::string& path) {
  static const std::regex param(R"(\{[^}/]+\})");
  std::string out;
  size_t last = 0;
  for (std::sregex_iterator it(path.begin(), path.end(), param), end; it != end; ++it) {
    out += std::regex_replace(path.substr(last, size_t(it->position()) - last),
                              std::regex(R"([.^$|()\[\]*+?\\])"), R"(\$&)");
    out += "([^/]+)";
    last = size_t(it->position() + it->length());
  }
  out += std::regex_replace(path.substr(last), std::regex(R"([.^$|()\[\]*+?\\])"), R"(\$&)");
  return out;
}

Handler guarded(Handler handler) {
  return [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
    try {
      handler(req, res);
    } catch (const api::ApiError& e) {
      send_error(res, e.code(), e.what());
    } catch (const MemoryBudgetError& e) {
      send_memory_refusal(res, e);
    } catch (const Error& e) {
      send_error(res, api::error_code_for(e.kind()), e.what());
    } catch (const std::bad_alloc&) {
      spdlog::error("{} {} (request {}): out of memory", req.method, req.path, current_request().id);
      send_error(res, api::ErrorCode::InsufficientStorage, "the server ran out of memory for this request");
    } catch (const std::exception& e) {
      // Its message may name server paths: it goes to the log, the client gets the request id.
      spdlog::error("{} {} (request {}): {}", req.method, req.path, current_request().id, e.what());
      send_error(res, api::ErrorCode::Internal,
                 "internal error; the server's log has it under request " + current_request().id);
    }
  };
}

// POST bodies are read through a content reader: httplib's default path caps bodies sent as
// application/x-www-form-urlencoded (curl's default for -d and --data-binary) at 8 KiB and parses
// them as forms, which would refuse an image uploaded with a plain `curl --data-binary @map.exr`.
httplib::Server::HandlerWithContentReader with_body(Handler handler, PostBody body) {
  return [handler = guarded(std::move(handler)), body](const httplib::Request& req, httplib::Response& res,
                                                       const httplib::ContentReader& reader) {
    if (req.is_multipart_form_data()) {
      send_error(res, api::ErrorCode::UnsupportedMediaType,
                 "send the file as the raw request body, not as multipart/form-data");
      return;
    }
    httplib::Request with = req;
    const bool complete = reader([&](const char* data, size_t n) {
      with.body.append(data, n);
      return true;
    });
    if (!complete) {
      if (res.status == 413 || request_body_over_limit())
        send_error(res, api::ErrorCode::PayloadTooLarge, kBodyTooLargeMessage);
      else
        send_error(res, api::ErrorCode::BadRequest, "the request body could not be read");
      return;
    }
    if (body == PostBody::Json && !with.body.empty() && !has_json_content_type(with)) {
      send_error(res, api::ErrorCode::UnsupportedMediaType,
                 "the body of " + req.method + " " + req.path +
                     " is JSON: send it as Content-Type: application/json");
      return;
    }
    handler(with, res);
  };
}

Handler with_query_policy(api::QueryPolicy policy, Handler handler) {
  return [policy = std::move(policy), handler = std::move(handler)](const httplib::Request& req,
                                                                    httplib::Response& res) {
    policy.check(req.params);
    handler(req, res);
  };
}

// Names the route in the request's context (for the access log and the metrics).
Handler with_route(const std::string& path, Handler handler) {
  return [path, handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
    current_request().route = path;
    handler(req, res);
  };
}

// ETag and Cache-Control on the route's answers, 304 for a matching If-None-Match: a whole body here, a
// content provider's bytes where send_reserved() makes it.
Handler with_caching(Caching caching, Handler handler) {
  return [caching, handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
    RequestContext& r = current_request();
    r.caching = caching;
    r.if_none_match = req.get_header_value("If-None-Match");
    handler(req, res);
    if (!res.body.empty() && !res.has_header("ETag") &&
        answer_not_modified(res, res.body, res.get_header_value("Content-Type")))
      res.body.clear();
  };
}

}  // namespace

void Router::add(const std::string& method, const std::string& path, Handler handler, PostBody body,
                 Caching caching) {
  const std::string pattern = to_regex(path);
  routes_.push_back({method, path, std::regex(pattern)});
  handler = with_query_policy(api::QueryPolicy(method, path), std::move(handler));
  if (caching != Caching::None) handler = with_caching(caching, std::move(handler));
  handler = with_route(path, std::move(handler));
  if (method == "GET")
    server_.Get(pattern, guarded(std::move(handler)));
  else if (method == "POST")
    server_.Post(pattern, with_body(std::move(handler), body));
  else if (method == "DELETE")
    server_.Delete(pattern, guarded(std::move(handler)));
}

void Router::get(const std::string& path, Handler handler, Caching caching) {
  add("GET", path, std::move(handler), PostBody::Json, caching);
}
void Router::post(const std::string& path, Handler handler, PostBody body) {
  add("POST", path, std::move(handler), body);
}
void Router::del(const std::string& path, Handler handler) {
  add("DELETE", path, std::move(handler));
}

std::vector<std::string> Router::methods_for(const std::string& request_path) const {
  std::vector<std::string> methods;
  for (const auto& route : routes_)
    if (std::regex_match(request_path, route.pattern) &&
        std::find(methods.begin(), methods.end(), route.method) == methods.end())
      methods.push_back(route.method);
  return methods;
}

}  // namespace lp::server

#pragma once
// Registers handlers on the httplib server under OpenAPI-style paths ("/api/v1/envmaps/{id}"),
// keeps the list of routes (checked against api/openapi.yaml by a test), refuses query parameters the
// document does not declare for the operation (api/query_policy.hpp), and turns every exception
// into a JSON error response so that no request can take the server down.
#include <httplib.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "api/error_codes.hpp"
#include "server/http/conditional_get.hpp"
#include "server/http/responses.hpp"

namespace lp::server {

struct Route {
  std::string method;
  std::string path;    // OpenAPI form
  std::regex pattern;  // what httplib matches request paths against
};

using Handler = std::function<void(const httplib::Request&, httplib::Response&)>;

// What a POST route reads from its body. A JSON body must say so (Content-Type: application/json):
// a browser can send text/plain or a form to another site without asking, but not JSON. A File is
// taken as sent, whatever its Content-Type.
enum class PostBody { Json, JsonOrImage, File };

class Router {
 public:
  explicit Router(httplib::Server& server) : server_(server) {}

  // `caching`: for a route whose answers are pure results, their ETag and Cache-Control
  // (conditional_get.hpp).
  void get(const std::string& path, Handler handler, Caching caching = Caching::None);
  void post(const std::string& path, Handler handler, PostBody body = PostBody::Json);
  void del(const std::string& path, Handler handler);

  const std::vector<Route>& routes() const { return routes_; }
  // The methods registered for the routes matching a request path, in registration order.
  std::vector<std::string> methods_for(const std::string& request_path) const;

 private:
  void add(const std::string& method, const std::string& path, Handler handler,
           PostBody body = PostBody::Json, Caching caching = Caching::None);

  httplib::Server& server_;
  std::vector<Route> routes_;
};

}  // namespace lp::server

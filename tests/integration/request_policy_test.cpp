// Requests outside what an endpoint serves: a method a known path does not serve gets 405 with the
// path's methods in Allow (from the server's route table); a query parameter api/openapi.yaml does not
// declare for the operation gets 400 naming it, on every endpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "api/openapi_parameters.hpp"
#include "api/params.hpp"
#include "support/http_reply.hpp"
#include "support/routes.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using test::Reply;

Reply send(const std::string& method, const std::string& target) {
  httplib::Request req;
  req.method = method;
  req.path = target;
  if (method == "POST") {
    req.body = "{}";
    req.set_header("Content-Type", "application/json");
  }
  return test::reply(test::default_server().client()->send(req));
}

std::string error_code(const Reply& r) {
  return r.body_json()["error"]["code"].get<std::string>();
}
std::string error_message(const Reply& r) {
  return r.body_json()["error"]["message"].get<std::string>();
}

// The Allow list each documented path should get: its registered methods, HEAD after GET.
std::map<std::string, std::vector<std::string>> allowed_by_path() {
  std::map<std::string, std::vector<std::string>> allowed;
  for (const auto& r : test::registered_routes()) {
    auto& methods = allowed[r.path];
    methods.push_back(r.method);
    if (r.method == "GET") methods.push_back("HEAD");
  }
  return allowed;
}

TEST(MethodPolicy, OtherMethodOnEveryKnownPathGets405WithItsMethods) {
  const auto allowed = allowed_by_path();
  ASSERT_GE(allowed.size(), 8u);
  for (const auto& [path, methods] : allowed) {
    const Reply r = send("PUT", test::fill_path(path, "default"));
    EXPECT_EQ(r.status, 405) << path << ": " << r.body;
    EXPECT_EQ(r.header("Allow"), api::join(methods, ", ")) << path;
    EXPECT_EQ(error_code(r), "method_not_allowed") << path;
  }
}

TEST(MethodPolicy, StatedCases) {
  Reply r = send("PATCH", "/api/v1/envmaps/default");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(r.header("Allow"), "GET, HEAD, DELETE");
  EXPECT_EQ(error_message(r), "PATCH is not allowed on /api/v1/envmaps/default (allowed: GET, HEAD, DELETE)");
  r = send("POST", "/api/v1/health");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(r.header("Allow"), "GET, HEAD");
  r = send("DELETE", "/api/v1/envmaps");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(r.header("Allow"), "GET, HEAD, POST");
  r = send("TRACE", "/api/v1/renders");
  EXPECT_EQ(r.status, 405);
  // Served methods and unknown paths are unchanged.
  EXPECT_EQ(send("HEAD", "/api/v1/health").status, 200);
  r = send("DELETE", "/api/v1/no-such-thing");
  EXPECT_EQ(r.status, 404);
  EXPECT_EQ(error_code(r), "not_found");
  EXPECT_EQ(r.header("Allow"), "");
  EXPECT_EQ(send("GET", "/api/v1/envmaps/default/no-such-view").status, 404);
}

TEST(QueryPolicy, EveryEndpointNamesAnUnknownParameter) {
  for (const auto& route : test::registered_routes()) {
    const Reply r = send(route.method, test::fill_path(route.path, "default") + "?lp_unknown=1");
    EXPECT_EQ(r.status, 400) << route.method << " " << route.path << ": " << r.body;
    EXPECT_EQ(error_code(r), "invalid_field") << route.path;
    EXPECT_NE(error_message(r).find("field 'lp_unknown': unknown parameter"), std::string::npos) << r.body;
  }
}

// The other direction: every parameter the document declares reaches its handler (whatever the
// handler then says about the value "1" or the placeholder ids).
TEST(QueryPolicy, EveryDocumentedParameterIsAccepted) {
  int checked = 0;
  for (const auto& route : test::registered_routes()) {
    for (const auto& name : api::documented_query_parameters(route.method, route.path)) {
      const Reply r = send(route.method, test::fill_path(route.path, "default") + "?" + name + "=1");
      ASSERT_NE(r.status, 0) << route.path;
      if (r.status >= 400) {
        EXPECT_EQ(error_message(r).find("unknown parameter"), std::string::npos) << r.body;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 20);
}

TEST(QueryPolicy, StatedMessages) {
  Reply r = send("GET", "/api/v1/envmaps/default/image?width=256");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(
      error_message(r),
      "field 'width': unknown parameter (expected one of: projection, size, face, format, exposure, gamma, "
      "tone_mapping)");
  r = send("GET", "/api/v1/envmaps/default/image?format=png&format=exr");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_message(r), "field 'format': given more than once");
  r = send("GET", "/api/v1/health?verbose=1");
  EXPECT_EQ(error_message(r), "field 'verbose': unknown parameter (this endpoint takes no query parameters)");
  r = send("GET", "/api/v1/fresnel?eta_i=1&eta_t=1.45&etat=1.5");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_message(r),
            "field 'etat': unknown parameter (expected one of: eta_i, eta_t, metal, eta, k, step, format)");
  // Documented parameters still work.
  r = send("GET", "/api/v1/envmaps/default/image?format=png&exposure=1&gamma=2.2");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.type(), "image/png");
}

}  // namespace
}  // namespace lp

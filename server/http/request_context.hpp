#pragma once
// What the server knows of the request being handled on this thread besides httplib's Request: when it
// began, its id, its Accept-Encoding (kept from httplib: compression.hpp), and the route that answered it
// with the route's caching. The transport starts it, the pre-routing handler and the router fill it in,
// the responses, the access log and the metrics read it. A request is handled from start to end on one
// thread (http_transport.hpp).
#include <chrono>
#include <cstdint>
#include <string>

#include "server/http/conditional_get.hpp"

namespace lp::server {

struct RequestContext {
  std::chrono::steady_clock::time_point start;
  uint64_t arrival = 0;  // the request's number, counted from 0 in the order requests begin in the process
  std::string id;        // its X-Request-Id (request_id.hpp)
  std::string client;    // the client's address: the peer's, or behind a trusted proxy the forwarded one
  std::string route;     // the OpenAPI path of the route that answered it; empty if none did
  std::string accept_encoding;
  Caching caching = Caching::None;  // the route's
  std::string if_none_match;        // the request's If-None-Match, on a route with a Caching
};

// The request of this thread.
RequestContext& current_request();
// Starts the context of a new request on this thread (its clock starts now), and counts it in flight
// until end_request_context().
void begin_request_context(std::string accept_encoding, std::string client);
void end_request_context();
// Requests begun and not yet answered, in the whole process.
int64_t requests_in_flight();

}  // namespace lp::server

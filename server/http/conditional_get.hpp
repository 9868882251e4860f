#pragma once
// ETag and Cache-Control on the answers of routes whose results are pure (Router::get's Caching), and
// If-None-Match answered with 304. The ETag is derived from the bytes of the body, so it changes exactly
// when they do (a map deleted and loaded again under its name, a render's next pass); it is weak when the
// body is sent gzipped (compression.hpp), whose bytes differ.
#include <httplib.h>

#include <string>
#include <string_view>

namespace lp::server {

enum class Caching {
  None,        // no ETag, no Cache-Control
  Revalidate,  // of the request and of what a name holds now (a map, a render): Cache-Control: no-cache
  Fresh,       // of the request alone (and the server's build): Cache-Control: max-age=kFreshSeconds
};

// How long a client may reuse a Fresh answer without asking again.
inline constexpr int kFreshSeconds = 3600;

// "\"<16 hex digits of a hash of the bytes>-<their length in hex>\"", or W/ and that.
std::string etag_of(std::string_view bytes, bool weak);
// Whether an If-None-Match header ("*" or a list of entity tags) names `etag` (the weak comparison).
bool etag_matches(std::string_view if_none_match, std::string_view etag);

// For a successful answer of the request on this thread with `body` of `content_type`: on a route with a
// Caching, sets ETag and Cache-Control, and returns true if the request's If-None-Match names the ETag:
// the status is then 304 and the caller sends no body.
bool answer_not_modified(httplib::Response& res, std::string_view body, std::string_view content_type);

}  // namespace lp::server

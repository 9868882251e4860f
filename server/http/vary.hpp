#pragma once
// The Vary header: the request headers an answer depends on (Accept-Encoding for compression, Origin for
// CORS), for caches between the server and its clients.
#include <httplib.h>

#include <string_view>

namespace lp::server {

// Adds `field` to the response's one Vary header (once).
void add_vary(httplib::Response& res, std::string_view field);

}  // namespace lp::server

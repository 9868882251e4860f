#pragma once
// The pieces every handler answers with: JSON bodies, the JSON error shape, path parameters and the
// Content-Type check of JSON bodies.
#include <httplib.h>

#include <nlohmann/json.hpp>
#include <string>

#include "api/error_codes.hpp"

namespace lp::server {

// Whether the request's Content-Type is application/json (parameters such as charset allowed).
bool has_json_content_type(const httplib::Request& req);

// Path parameter n (1-based, in order of appearance) of a route registered with {name} segments.
std::string path_param(const httplib::Request& req, size_t n);

// Writes {"error":{"code":..,"message":..,"request_id":..}} with the code's status; the id is the response's
// X-Request-Id, set to a new one if it has none.
void send_error(httplib::Response& res, api::ErrorCode code, const std::string& message);
void send_json(httplib::Response& res, const nlohmann::json& body, int status = 200);

}  // namespace lp::server

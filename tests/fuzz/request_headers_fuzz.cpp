// The request headers the server reads itself, as a client sends them: Accept-Encoding (gzip or not),
// If-None-Match (against an ETag), X-Request-Id (kept or replaced) and Authorization (a bearer token),
// one a line in that order. Nothing may throw; a kept request id must be safe, and a refusal must be a
// 401 JSON error with its challenge.
#include <httplib.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_input.hpp"
#include "server/http/bearer_auth.hpp"
#include "server/http/compression.hpp"
#include "server/http/conditional_get.hpp"
#include "server/http/request_id.hpp"

namespace {

std::string line(const std::string& text, size_t n) {
  size_t start = 0;
  for (size_t i = 0; i < n && start != std::string::npos; ++i) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos) return "";
  return text.substr(start, text.find('\n', start) - start);
}

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = lp::fuzz::as_text(data, size);
  const std::string accept_encoding = line(text, 0), if_none_match = line(text, 1), id = line(text, 2),
                    authorization = line(text, 3);
  const bool gzip = lp::server::accepts_gzip(accept_encoding);
  const std::string etag = lp::server::etag_of(text, gzip);
  lp::server::etag_matches(if_none_match, etag);

  httplib::Request req;
  req.path = "/api/v1/envmaps";
  req.set_header("X-Request-Id", id);
  req.set_header("Authorization", authorization);
  const std::string kept = lp::server::request_id_for(req);
  require(lp::server::is_safe_request_id(kept));
  require(kept == req.get_header_value("X-Request-Id") || kept.size() == 16);  // (as httplib reads it)

  httplib::Response res;
  res.set_header("X-Request-Id", kept);
  if (lp::server::BearerAuth("0123456789abcdef0123456789abcdef").refuse(req, res)) {
    require(res.status == 401 && res.get_header_value("WWW-Authenticate").starts_with("Bearer realm="));
    require(nlohmann::json::parse(res.body)["error"]["code"] == "unauthorized");
  }
  return 0;
}

#include "server/http/conditional_get.hpp"

#include <fmt/format.h>

#include <functional>

#include "server/http/compression.hpp"
#include "server/http/request_context.hpp"
#include "server/http/vary.hpp"

namespace lp::server {
namespace {

std::string_view opaque(std::string_view etag) {
  return etag.starts_with("W/") ? etag.substr(2) : etag;
}

std::string cache_control(Caching caching) {
  return caching == Caching::Fresh ? fmt::format("max-age={}", kFreshSeconds) : "no-cache";
}

}  // namespace

std::string etag_of(std::string_view bytes, bool weak) {
  return fmt::format("{}\"{:016x}-{:x}\"", weak ? "W/" : "", std::hash<std::string_view>{}(bytes),
                     bytes.size());
}

bool etag_matches(std::string_view if_none_match, std::string_view etag) {
  for (size_t start = 0; start < if_none_match.size();) {
    const size_t end = std::min(if_none_match.find(',', start), if_none_match.size());
    std::string_view tag = if_none_match.substr(start, end - start);
    while (!tag.empty() && (tag.front() == ' ' || tag.front() == '\t')) tag.remove_prefix(1);
    while (!tag.empty() && (tag.back() == ' ' || tag.back() == '\t')) tag.remove_suffix(1);
    if (tag == "*" || (!tag.empty() && opaque(tag) == opaque(etag))) return true;
    start = end + 1;
  }
  return false;
}

bool answer_not_modified(httplib::Response& res, std::string_view body, std::string_view content_type) {
  const RequestContext& r = current_request();
  if (r.caching == Caching::None || (res.status != -1 && res.status != 200)) return false;
  const std::string etag = etag_of(body, gzips(content_type, body.size(), r.accept_encoding));
  res.headers.erase("ETag");
  res.set_header("ETag", etag);
  res.headers.erase("Cache-Control");
  res.set_header("Cache-Control", cache_control(r.caching));
  if (is_compressible(content_type)) add_vary(res, "Accept-Encoding");
  if (!etag_matches(r.if_none_match, etag)) return false;
  res.status = 304;
  return true;
}

}  // namespace lp::server

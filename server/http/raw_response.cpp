#include "server/http/raw_response.hpp"

#include <fmt/format.h>

#include "server/http/request_id.hpp"
#include "server/http/responses.hpp"

namespace lp::server {
namespace {

const char* reason_phrase(int status) {
  switch (status) {
    case 400:
      return "Bad Request";
    case 408:
      return "Request Timeout";
    case 413:
      return "Payload Too Large";
    case 414:
      return "URI Too Long";
    case 431:
      return "Request Header Fields Too Large";
    case 501:
      return "Not Implemented";
    case 503:
      return "Service Unavailable";
    case 505:
      return "HTTP Version Not Supported";
  }
  return "Error";
}

}  // namespace

std::string raw_error_response(api::ErrorCode code, const std::string& message,
                               const std::string& extra_headers) {
  httplib::Response res;
  send_error(res, code, message);
  const int status = res.status;
  return fmt::format(
      "HTTP/1.1 {} {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\n{}: {}\r\nConnection: "
      "close\r\n{}\r\n{}",
      status, reason_phrase(status), res.body.size(), kRequestIdHeader,
      res.get_header_value(kRequestIdHeader), extra_headers, res.body);
}

}  // namespace lp::server

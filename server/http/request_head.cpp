#include "server/http/request_head.hpp"

#include <fmt/format.h>
#include <strings.h>

#include <algorithm>
#include <vector>

namespace lp::server {
namespace {

bool is_control(unsigned char c) {
  return c < 0x20 || c == 0x7f;
}

bool is_token(std::string_view s) {
  static constexpr std::string_view kSeparators = "()<>@,;:\\\"/[]?={} \t";
  return !s.empty() && std::none_of(s.begin(), s.end(), [](char c) {
    return is_control(static_cast<unsigned char>(c)) || (c & 0x80) ||
           kSeparators.find(c) != std::string_view::npos;
  });
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && strncasecmp(a.data(), b.data(), a.size()) == 0;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The path as handlers and the static file handler see it (percent-decoded) holds a control byte.
bool path_has_control_byte(std::string_view target) {
  const std::string_view path = target.substr(0, target.find('?'));
  for (size_t i = 0; i < path.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(path[i]);
    if (c == '%' && i + 2 < path.size() && hex_value(path[i + 1]) >= 0 && hex_value(path[i + 2]) >= 0) {
      c = static_cast<unsigned char>(hex_value(path[i + 1]) * 16 + hex_value(path[i + 2]));
      i += 2;
    }
    if (is_control(c)) return true;
  }
  return false;
}

std::vector<std::string_view> split_lines(std::string_view head) {
  std::vector<std::string_view> lines;
  while (!head.empty()) {
    const size_t end = head.find('\n');
    std::string_view line = head.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty()) lines.push_back(line);
    head.remove_prefix(end == std::string_view::npos ? head.size() : end + 1);
  }
  return lines;
}

CheckedHead reject(api::ErrorCode code, std::string message) {
  return {std::nullopt, {code, std::move(message)}};
}

CheckedHead bad_request(std::string message) {
  return reject(api::ErrorCode::BadRequest, std::move(message));
}

// What the header lines say about the body, gathered while the head is rebuilt.
struct BodyHeaders {
  std::optional<uint64_t> content_length;
  std::optional<std::string_view> transfer_encoding;
};

std::optional<CheckedHead> check_content_length(std::string_view value, BodyHeaders& body) {
  if (value.empty() || value.size() > 18 ||
      !std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return bad_request(
        fmt::format("Content-Length must be a non-negative decimal integer, got '{:.32}'", value));
  const uint64_t length = std::stoull(std::string(value));
  if (body.content_length && *body.content_length != length)
    return bad_request("the request has Content-Length headers that disagree");
  body.content_length = length;
  return std::nullopt;
}

std::optional<CheckedHead> check_request_line(std::string_view line) {
  const size_t sp1 = line.find(' ');
  const size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos)
    return bad_request("malformed request line");
  const std::string_view method = line.substr(0, sp1), target = line.substr(sp1 + 1, sp2 - sp1 - 1),
                         version = line.substr(sp2 + 1);
  if (!is_token(method) || target.empty()) return bad_request("malformed request line");
  if (version != "HTTP/1.1" && version != "HTTP/1.0")
    return reject(api::ErrorCode::HttpVersionNotSupported, "only HTTP/1.0 and HTTP/1.1 are served");
  if (path_has_control_byte(target))
    return reject(api::ErrorCode::InvalidPath,
                  "the path holds a control character (a byte below 0x20 or 0x7F, e.g. %00)");
  return std::nullopt;
}

}  // namespace

HeadScanner::State HeadScanner::fail(api::ErrorCode code, std::string message) {
  error_ = {code, std::move(message)};
  return State::Error;
}

HeadScanner::State HeadScanner::scan(std::string_view input) {
  while (pos_ < input.size()) {
    const char c = input[pos_++];
    const size_t length = pos_ - line_start_;
    if (c != '\n') {
      if (lines_ == 0 && length > kMaxRequestLineBytes)
        return fail(api::ErrorCode::UriTooLong,
                    fmt::format("the request line is over {} bytes", kMaxRequestLineBytes));
      if (length > kMaxHeaderLineBytes)
        return fail(api::ErrorCode::HeaderTooLarge,
                    fmt::format("a header line is over {} bytes", kMaxHeaderLineBytes));
      if (pos_ > kMaxHeadBytes)
        return fail(api::ErrorCode::HeaderTooLarge,
                    fmt::format("the request headers are over {} bytes", kMaxHeadBytes));
      continue;
    }
    const bool blank = length == 1 || (length == 2 && input[pos_ - 2] == '\r');
    if (blank && lines_ > 0) return State::Complete;
    if (++lines_ > kMaxHeaderLines + 1)
      return fail(api::ErrorCode::HeaderTooLarge,
                  fmt::format("the request has over {} header lines", kMaxHeaderLines));
    line_start_ = pos_;
  }
  return State::NeedMore;
}

CheckedHead check_request_head(std::string_view head, uint64_t max_body) {
  const auto lines = split_lines(head);
  if (lines.empty()) return bad_request("empty request");
  const bool http10 = lines[0].ends_with("HTTP/1.0");
  if (auto error = check_request_line(lines[0])) return *error;

  RequestHead out;
  out.text.reserve(head.size());
  out.text.append(lines[0]).append("\r\n");
  BodyHeaders body;
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    const size_t colon = line.find(':');
    if (line.front() == ' ' || line.front() == '\t')
      return bad_request("folded header lines are not accepted");
    if (colon == std::string_view::npos || !is_token(line.substr(0, colon)))
      return bad_request("malformed header line");
    const std::string_view name = line.substr(0, colon), value = trim(line.substr(colon + 1));
    if (std::any_of(value.begin(), value.end(),
                    [](char c) { return c != '\t' && is_control(static_cast<unsigned char>(c)); }))
      return bad_request(fmt::format("header {:.64} holds a control character", name));
    if (iequals(name, "Content-Length")) {
      if (auto error = check_content_length(value, body)) return *error;
    } else if (iequals(name, "Transfer-Encoding")) {
      if (body.transfer_encoding)
        return reject(api::ErrorCode::NotImplemented, "only one transfer coding, chunked, is accepted");
      body.transfer_encoding = value;
      continue;  // the transport decodes the body: httplib reads it as a body that ends with the stream
    } else if (iequals(name, "Range") || iequals(name, "If-Range")) {
      continue;  // ranges are ignored: every response is whole
    } else if (iequals(name, "Accept-Encoding")) {
      if (!out.accept_encoding.empty()) out.accept_encoding += ", ";
      out.accept_encoding.append(value);
      continue;
    } else if (iequals(name, "X-Forwarded-For")) {
      if (!out.forwarded_for.empty()) out.forwarded_for += ", ";
      out.forwarded_for.append(value);
    }
    out.text.append(line).append("\r\n");
  }
  out.text.append("\r\n");

  if (body.transfer_encoding) {
    if (!iequals(*body.transfer_encoding, "chunked"))
      return reject(api::ErrorCode::NotImplemented, "only the chunked transfer coding is accepted");
    if (body.content_length)
      return bad_request("a request cannot have both Content-Length and Transfer-Encoding");
    if (http10) return bad_request("HTTP/1.0 requests cannot use Transfer-Encoding");
    out.body = {BodyFraming::Kind::Chunked, 0, max_body};
  } else if (body.content_length) {
    if (*body.content_length > max_body) return reject(api::ErrorCode::PayloadTooLarge, kBodyTooLargeMessage);
    out.body = {BodyFraming::Kind::Length, *body.content_length, max_body};
  }
  return {std::move(out), {}};
}

}  // namespace lp::server

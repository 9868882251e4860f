#pragma once
// The request line and header block of one HTTP/1.x request, read and checked by the transport before
// httplib sees them: bounded in size and line count, with a body length known in advance (or a chunked
// body), no control byte in the path, and no Range header (every response is whole, so no request can
// ask for a response larger than the resource).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "api/error_codes.hpp"
#include "server/http/body_framing.hpp"

namespace lp::server {

inline constexpr size_t kMaxRequestLineBytes = 8192;  // longer: 414
inline constexpr size_t kMaxHeaderLineBytes = 8192;   // longer: 431
inline constexpr size_t kMaxHeaderLines = 100;        // more: 431
inline constexpr size_t kMaxHeadBytes = 64 * 1024;    // request line and headers together; more: 431

// An answer the transport gives itself, in the JSON error shape.
struct HeadError {
  api::ErrorCode code = api::ErrorCode::BadRequest;
  std::string message;
};

// Finds the end of the head in bytes that arrive piece by piece (each call resumes where the last one
// stopped), enforcing the size and line limits before the head is complete.
class HeadScanner {
 public:
  enum class State { NeedMore, Complete, Error };
  State scan(std::string_view input);
  size_t head_length() const { return pos_; }  // when Complete: bytes up to and including the blank line
  const HeadError& error() const { return error_; }

 private:
  State fail(api::ErrorCode code, std::string message);

  size_t pos_ = 0;
  size_t line_start_ = 0;
  size_t lines_ = 0;
  HeadError error_;
};

// A checked head: the text httplib parses (Range, Transfer-Encoding and Accept-Encoding removed), how its
// body is framed, and its Accept-Encoding (the server compresses responses itself: compression.hpp).
struct RequestHead {
  std::string text;
  BodyFraming body;
  std::string accept_encoding;  // the Accept-Encoding headers' values, joined with ", "
  std::string forwarded_for;    // the X-Forwarded-For headers' values, joined with ", "
};

// Checks a complete head (as delimited by HeadScanner); `max_body` is the largest body accepted (413).
struct CheckedHead {
  std::optional<RequestHead> head;
  HeadError error;  // when !head
};
CheckedHead check_request_head(std::string_view head, uint64_t max_body);

}  // namespace lp::server

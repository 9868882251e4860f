#pragma once
// How the body of a request is delimited on the connection.
#include <cstdint>

namespace lp::server {

// The answer (413) to a body over --max-upload-mb, whether its length was declared or found while reading.
inline constexpr const char* kBodyTooLargeMessage =
    "the request body is over the server's limit (--max-upload-mb)";

struct BodyFraming {
  enum class Kind { None, Length, Chunked };
  Kind kind = Kind::None;
  uint64_t length = 0;    // Kind::Length
  uint64_t max_body = 0;  // Kind::Chunked: the most decoded bytes accepted
};

}  // namespace lp::server

#pragma once
// gzip of response bodies, as the server decides it rather than httplib: Debian builds httplib with zlib
// and brotli, and it would compress every JSON or text body of any size whenever Accept-Encoding merely
// names gzip or br (q=0 too), without Vary. So the transport takes Accept-Encoding out of the request
// (request_head.hpp) and, once a response is made, compress_response() gzips a body of a compressible type
// of at least kGzipMinBytes when the client accepts gzip, and marks every such response Vary:
// Accept-Encoding.
#include <httplib.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace lp::server {

// Smaller bodies are sent as they are: gzip's header and trailer (18 bytes) and a deflate block leave
// little to save in less than a kilobyte, and the response fits in one packet anyway.
inline constexpr size_t kGzipMinBytes = 1024;

// Whether an Accept-Encoding header accepts gzip: "gzip" or "x-gzip", or "*" when gzip is not named,
// with a q-value above 0.
bool accepts_gzip(std::string_view accept_encoding);
// JSON, YAML, text (event streams excepted), JavaScript and SVG: the types worth compressing.
bool is_compressible(std::string_view content_type);
// Whether a body of `size` bytes of `content_type` is sent gzipped to a client with `accept_encoding`.
bool gzips(std::string_view content_type, size_t size, std::string_view accept_encoding);
std::string gzip(std::string_view bytes);

// Gzips the body of `res` (a whole body, not a content provider) when gzips() says so, setting
// Content-Encoding and Content-Length; a response of a compressible type gets Vary: Accept-Encoding.
void compress_response(std::string_view accept_encoding, httplib::Response& res);

}  // namespace lp::server

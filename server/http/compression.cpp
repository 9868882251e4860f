#include "server/http/compression.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "server/http/vary.hpp"

namespace lp::server {
namespace {

// The deflate level: 6, zlib's default; JSON of numbers shrinks to about a third.
constexpr int kGzipLevel = 6;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool iequals(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  });
}

// The q-value of one element of Accept-Encoding ("gzip;q=0.5" -> 0.5; absent: 1).
double quality(std::string_view parameters) {
  for (size_t start = 0; start < parameters.size();) {
    const size_t end = std::min(parameters.find(';', start), parameters.size());
    const std::string_view p = trim(parameters.substr(start, end - start));
    if (p.size() > 2 && (p[0] == 'q' || p[0] == 'Q') && p[1] == '=')
      return std::strtod(std::string(p.substr(2)).c_str(), nullptr);
    start = end + 1;
  }
  return 1;
}

}  // namespace

bool accepts_gzip(std::string_view accept_encoding) {
  std::optional<double> gzip_q, any_q;
  for (size_t start = 0; start <= accept_encoding.size();) {
    const size_t end = std::min(accept_encoding.find(',', start), accept_encoding.size());
    const std::string_view element = accept_encoding.substr(start, end - start);
    const size_t semicolon = std::min(element.find(';'), element.size());
    const std::string_view coding = trim(element.substr(0, semicolon));
    const double q = quality(element.substr(semicolon));
    if (iequals(coding, "gzip") || iequals(coding, "x-gzip"))
      gzip_q = std::max(gzip_q.value_or(0), q);
    else if (coding == "*")
      any_q = q;
    start = end + 1;
  }
  return gzip_q ? *gzip_q > 0 : any_q.value_or(0) > 0;
}

bool is_compressible(std::string_view content_type) {
  const std::string_view type = trim(content_type.substr(0, content_type.find(';')));
  if (type.starts_with("text/")) return type != "text/event-stream";
  return type == "application/json" || type == "application/yaml" || type == "application/javascript" ||
         type == "image/svg+xml";
}

bool gzips(std::string_view content_type, size_t size, std::string_view accept_encoding) {
  return is_compressible(content_type) && size >= kGzipMinBytes && accepts_gzip(accept_encoding);
}

std::string gzip(std::string_view bytes) {
  z_stream z{};
  if (deflateInit2(&z, kGzipLevel, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("gzip: deflateInit2 failed");
  std::string out(deflateBound(&z, uLong(bytes.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = uInt(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  const int result = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (result != Z_STREAM_END) throw std::runtime_error("gzip: deflate did not finish");
  return out;
}

void compress_response(std::string_view accept_encoding, httplib::Response& res) {
  const std::string type = res.get_header_value("Content-Type");
  if (!is_compressible(type)) return;
  add_vary(res, "Accept-Encoding");
  if (res.has_header("Content-Encoding") || !gzips(type, res.body.size(), accept_encoding)) return;
  res.body = gzip(res.body);
  res.set_header("Content-Encoding", "gzip");
  res.headers.erase("Content-Length");
  res.set_header("Content-Length", std::to_string(res.body.size()));
}

}  // namespace lp::server

// Response compression and conditional GETs: which Accept-Encoding headers accept gzip, which types are
// compressed, gzip's output read back by zlib, and If-None-Match matched by the weak comparison.
#include "server/http/compression.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

#include "api/openapi.hpp"
#include "server/http/browser_policy.hpp"
#include "server/http/conditional_get.hpp"
#include "server/http/vary.hpp"

namespace lp::server {
namespace {

std::string gunzip(const std::string& bytes) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  std::string out(1 << 20, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = uInt(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

TEST(Compression, AcceptEncodingWithQValues) {
  for (const char* yes : {"gzip", "GZIP", "gzip, deflate, br", "br;q=1.0, gzip;q=0.5", "x-gzip", "*",
                          "identity, *;q=0.1", "gzip;q=0, gzip;q=1"})
    EXPECT_TRUE(accepts_gzip(yes)) << yes;
  for (const char* no : {"", "identity", "br", "deflate, br", "gzip;q=0", "gzip; q=0.000", "*, gzip;q=0",
                         "*;q=0", "gzipx", "notgzip"})
    EXPECT_FALSE(accepts_gzip(no)) << no;
}

TEST(Compression, CompressibleTypes) {
  for (const char* yes :
       {"application/json", "application/json; charset=utf-8", "text/csv", "text/plain; version=0.0.4",
        "application/yaml", "text/html", "application/javascript", "image/svg+xml"})
    EXPECT_TRUE(is_compressible(yes)) << yes;
  for (const char* no : {"image/png", "image/x-exr", "application/octet-stream", "text/event-stream", ""})
    EXPECT_FALSE(is_compressible(no)) << no;
  EXPECT_FALSE(gzips("application/json", kGzipMinBytes - 1, "gzip"));
  EXPECT_TRUE(gzips("application/json", kGzipMinBytes, "gzip"));
  EXPECT_FALSE(gzips("image/png", kGzipMinBytes, "gzip"));
}

TEST(Compression, GzipReadsBackAndShrinksJson) {
  std::string json = "[";
  for (int i = 0; i < 10000; ++i) json += std::to_string(i * 0.001) + ",";
  json.back() = ']';
  const std::string gz = gzip(json);
  EXPECT_EQ(gz.substr(0, 2), "\x1f\x8b");
  EXPECT_EQ(gunzip(gz), json);
  EXPECT_LT(gz.size(), json.size() / 3);
  EXPECT_EQ(gunzip(gzip("")), "");
}

TEST(Compression, VaryCollectsFields) {
  httplib::Response res;
  add_vary(res, "Origin");
  add_vary(res, "Accept-Encoding");
  add_vary(res, "Origin");
  EXPECT_EQ(res.get_header_value("Vary"), "Origin, Accept-Encoding");
  EXPECT_EQ(res.get_header_value_count("Vary"), 1u);
}

TEST(ConditionalGet, EtagsAndTheWeakComparison) {
  const std::string strong = etag_of("abc", false), weak = etag_of("abc", true);
  EXPECT_EQ(weak, "W/" + strong);
  EXPECT_NE(etag_of("abd", false), strong);
  EXPECT_NE(etag_of(std::string("abc\0", 4), false), strong);
  EXPECT_TRUE(etag_matches(strong, strong));
  EXPECT_TRUE(etag_matches(weak, strong));
  EXPECT_TRUE(etag_matches(strong, weak));
  EXPECT_TRUE(etag_matches("\"x\", " + weak + " ,\"y\"", strong));
  EXPECT_TRUE(etag_matches("*", strong));
  EXPECT_FALSE(etag_matches("", strong));
  EXPECT_FALSE(etag_matches("\"x\", \"y\"", strong));
  EXPECT_FALSE(etag_matches(etag_of("abd", false), strong));
}

// api/openapi.yaml states the threshold, the max-ages and the token length as declared here.
TEST(Compression, TheOpenApiDocumentStatesTheThresholdAndMaxAges) {
  const std::string_view doc = api::openapi_document();
  EXPECT_NE(doc.find(fmt::format("and Max-Age {};", kPreflightMaxAgeS)), std::string::npos);
  EXPECT_NE(doc.find(fmt::format("of {} bytes or more is sent gzipped", kGzipMinBytes)), std::string::npos);
  EXPECT_NE(doc.find(fmt::format("`max-age={}` for a result of the request alone", kFreshSeconds)),
            std::string::npos);
}

}  // namespace
}  // namespace lp::server

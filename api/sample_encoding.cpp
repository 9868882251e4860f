#include "api/sample_encoding.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace lp::api {

namespace {

// A sample's values after its pixel, in the order of kSampleRecordLayout.
std::array<float, kSampleRecordFloats - 2> values(const EnvSample& s) {
  return {s.u,   s.v,   s.direction.x, s.direction.y, s.direction.z, s.theta,
          s.phi, s.pdf, s.radiance.x,  s.radiance.y,  s.radiance.z};
}

// JSON has no token for NaN or Inf: a sample holding one is a bug upstream, never written.
void check_finite(const EnvSample& s) {
  for (float v : values(s))
    if (!std::isfinite(v))
      throw std::logic_error(fmt::format("sample at pixel ({}, {}) is not finite", s.pixel_x, s.pixel_y));
}

}  // namespace

// One sample's JSON object or CSV row, written into a fixed buffer with std::to_chars: floats in their
// shortest round-trip form (JSON clients read back the exact values), and no format string parsed per sample,
// which made up most of the cost of a small /samples request.
class SampleTextWriter {
 public:
  void literal(std::string_view text) {
    std::memcpy(at_, text.data(), text.size());
    at_ += text.size();
  }
  template <typename T>
  void number(T value) {
    at_ = std::to_chars(at_, end(), value).ptr;
  }
  template <typename T, typename... Rest>
  void array(T first, Rest... rest) {
    *at_++ = '[';
    number(first);
    ((*at_++ = ',', number(rest)), ...);
    *at_++ = ']';
  }
  void append_to(std::string& out) const { out.append(buffer_, size_t(at_ - buffer_)); }

 private:
  char* end() { return buffer_ + sizeof(buffer_); }
  // JSON literals take 70 bytes, CSV separators 13; 11 floats at most 15 bytes each and 2 ints at most 11
  // each.
  char buffer_[384];
  char* at_ = buffer_;
};

void append_sample_json(std::string& out, const EnvSample& s) {
  check_finite(s);
  SampleTextWriter w;
  w.literal(R"({"pixel":)");
  w.array(s.pixel_x, s.pixel_y);
  w.literal(R"(,"uv":)");
  w.array(s.u, s.v);
  w.literal(R"(,"direction":)");
  w.array(s.direction.x, s.direction.y, s.direction.z);
  w.literal(R"(,"theta":)");
  w.number(s.theta);
  w.literal(R"(,"phi":)");
  w.number(s.phi);
  w.literal(R"(,"pdf":)");
  w.number(s.pdf);
  w.literal(R"(,"radiance":)");
  w.array(s.radiance.x, s.radiance.y, s.radiance.z);
  w.literal("}");
  w.append_to(out);
}

void append_sample_csv(std::string& out, const EnvSample& s) {
  check_finite(s);
  SampleTextWriter w;
  w.number(s.pixel_x);
  w.literal(",");
  w.number(s.pixel_y);
  for (float v : values(s)) {
    w.literal(",");
    w.number(v);
  }
  w.literal("\n");
  w.append_to(out);
}

void append_sample_binary(std::string& out, const EnvSample& s) {
  static_assert(std::endian::native == std::endian::little, "binary records are little-endian");
  const float pixel[2] = {float(s.pixel_x), float(s.pixel_y)};
  const auto rest = values(s);
  const size_t at = out.size();
  out.resize(at + sizeof(pixel) + sizeof(rest));
  std::memcpy(out.data() + at, pixel, sizeof(pixel));
  std::memcpy(out.data() + at + sizeof(pixel), rest.data(), sizeof(rest));
}

}  // namespace lp::api

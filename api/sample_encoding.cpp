#include "api/sample_encoding.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <iterator>

#include <fmt/format.h>

namespace lp::api {

namespace {

bool finite(const EnvSample& s) {
  for (float v : {s.u, s.v, s.direction.x, s.direction.y, s.direction.z, s.theta, s.phi, s.pdf, s.radiance.x,
                  s.radiance.y, s.radiance.z})
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

// fmt prints floats in their shortest round-trip form, so JSON clients read back the exact values.
// JSON has no token for NaN or Inf: a sample holding one is a bug upstream, never written.
void append_sample_json(std::string& out, const EnvSample& s) {
  if (!finite(s)) throw std::logic_error(fmt::format("sample at pixel ({}, {}) is not finite", s.pixel_x, s.pixel_y));
  fmt::format_to(std::back_inserter(out),
                 R"({{"pixel":[{},{}],"uv":[{},{}],"direction":[{},{},{}],"theta":{},"phi":{},"pdf":{},"radiance":[{},{},{}]}})",
                 s.pixel_x, s.pixel_y, s.u, s.v, s.direction.x, s.direction.y, s.direction.z, s.theta, s.phi, s.pdf,
                 s.radiance.x, s.radiance.y, s.radiance.z);
}

void append_sample_binary(std::string& out, const EnvSample& s) {
  static_assert(std::endian::native == std::endian::little, "binary records are little-endian");
  const float record[kSampleRecordFloats] = {float(s.pixel_x), float(s.pixel_y), s.u, s.v, s.direction.x,
                                             s.direction.y, s.direction.z, s.theta, s.phi, s.pdf,
                                             s.radiance.x, s.radiance.y, s.radiance.z};
  const size_t at = out.size();
  out.resize(at + sizeof(record));
  std::memcpy(out.data() + at, record, sizeof(record));
}

}  // namespace lp::api

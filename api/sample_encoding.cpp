#include "api/sample_encoding.hpp"

#include <bit>
#include <cstring>
#include <iterator>

#include <fmt/format.h>

namespace lp::api {

// fmt prints floats in their shortest round-trip form, so JSON clients read back the exact values.
void append_sample_json(std::string& out, const EnvSample& s) {
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

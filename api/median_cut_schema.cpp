#include "api/median_cut_schema.hpp"

#include <iterator>

#include <fmt/format.h>

namespace lp::api {
namespace {

void append_light(std::string& out, const MedianCutLight& l) {
  fmt::format_to(std::back_inserter(out),
                 R"({{"direction":[{},{},{}],"pixel":[{},{}],"uv":[{},{}],)"
                 R"("region":{{"x0":{},"y0":{},"x1":{},"y1":{}}},"power":[{},{},{}],"energy":{}}})",
                 l.direction.x, l.direction.y, l.direction.z, l.pixel_x, l.pixel_y, l.u, l.v, l.region.x0,
                 l.region.y0, l.region.x1, l.region.y1, l.power[0], l.power[1], l.power[2], l.energy);
}

}  // namespace

std::string median_cut_json(const MedianCutResult& r, double elapsed_ms, bool cached) {
  std::string out;
  out.reserve(256 + r.lights.size() * 230);
  fmt::format_to(std::back_inserter(out), R"({{"count":{},"placement":"{}","split":"{}","luminance":"{}","lights":[)",
                 r.lights.size(), enum_name(r.params.placement), enum_name(r.params.split),
                 enum_name(r.params.luminance));
  for (size_t i = 0; i < r.lights.size(); ++i) {
    if (i > 0) out.push_back(',');
    append_light(out, r.lights[i]);
  }
  fmt::format_to(std::back_inserter(out),
                 R"(],"power":[{},{},{}],"energy_min":{},"energy_max":{},"elapsed_ms":{},"cached":{}}})", r.power[0],
                 r.power[1], r.power[2], r.energy_min, r.energy_max, elapsed_ms, cached);
  return out;
}

}  // namespace lp::api

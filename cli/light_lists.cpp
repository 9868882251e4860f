#include "cli/light_lists.hpp"

#include <fmt/format.h>

#include <iterator>

namespace lp::cli {
namespace {

// The comment at the head of a list: what the lights are, and their total (numbers in their shortest
// text that reads back as the same value).
std::string description(const MedianCutResult& r, std::string_view line_start) {
  return fmt::format(
      "{} median-cut lights ({} split, {} placement) from Lightprobe; world frame z up.\n"
      "{}They add up to the map's power: {} {} {}",
      r.lights.size(), enum_name(r.params.split), enum_name(r.params.placement), line_start, r.power[0],
      r.power[1], r.power[2]);
}

}  // namespace

std::string lights_csv(const MedianCutResult& r) {
  std::string out = "dir_x,dir_y,dir_z,pixel_x,pixel_y,u,v,x0,y0,x1,y1,power_r,power_g,power_b,energy\n";
  for (const MedianCutLight& l : r.lights)
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", l.direction.x,
                   l.direction.y, l.direction.z, l.pixel_x, l.pixel_y, l.u, l.v, l.region.x0, l.region.y0,
                   l.region.x1, l.region.y1, l.power[0], l.power[1], l.power[2], l.energy);
  return out;
}

std::string lights_pbrt(const MedianCutResult& r) {
  std::string out = "# " + description(r, "# ") + "\nAttributeBegin\n";
  for (const MedianCutLight& l : r.lights)
    fmt::format_to(std::back_inserter(out),
                   "  LightSource \"distant\" \"point3 from\" [{} {} {}] \"point3 to\" [0 0 0]\n"
                   "    \"rgb L\" [{} {} {}] \"float scale\" 1\n",
                   l.direction.x, l.direction.y, l.direction.z, l.power[0], l.power[1], l.power[2]);
  out += "AttributeEnd\n";
  return out;
}

}  // namespace lp::cli

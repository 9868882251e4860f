#include "api/light_export.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "api/api_error.hpp"
#include "api/light_export_writers.hpp"

namespace lp::api {

LightSet median_cut_light_set(const MedianCutResult& r, double illuminance) {
  LightSet set{fmt::format("{} median-cut lights ({} split, {} placement) from Lightprobe", r.lights.size(),
                           enum_name(r.params.split), enum_name(r.params.placement)),
               {},
               illuminance};
  for (size_t i = 0; i < r.lights.size(); ++i) {
    const MedianCutLight& l = r.lights[i];
    const double n = std::sqrt(double(dot(l.direction, l.direction)));
    set.lights.push_back(
        {fmt::format("light_{}", i), {l.direction.x / n, l.direction.y / n, l.direction.z / n}, l.power, 0});
  }
  return set;
}

LightSet sun_light_set(const Sun& sun, double illuminance) {
  return {fmt::format("the map's sun from Lightprobe ({:.3g} of its power, {:.3g} degrees across)", sun.share,
                      2 * sun.angular_radius * 180 / std::numbers::pi),
          {{"sun", sun.axis, sun.irradiance, sun.angular_radius}},
          illuminance};
}

LightSet no_sun_light_set(const std::string& reason, double illuminance) {
  return {"no sun in the map (" + reason + "), from Lightprobe", {}, illuminance};
}

LightExportQuery parse_light_export_query(const Query& query) {
  LightExportQuery out;
  out.format = query_enum(query, "format", out.format);
  out.frame = query_enum(query, "frame", out.frame);
  if (query.count("frame") && out.format != LightFormat::Mitsuba)
    throw invalid_field("frame", "applies to format mitsuba only");
  return out;
}

Direction gltf_direction(const Direction& w) {
  return {w[0], w[2], -w[1]};
}

Direction mitsuba_direction(const Direction& w) {
  return {w[1], w[2], -w[0]};
}

std::array<double, 4> rotation_from_z(const Direction& to) {
  // q = (1 + z.to, z x to), normalised; opposite to +Z: half a turn about x.
  const double w = 1 + to[2];
  if (w < 1e-12) return {0, 1, 0, 0};
  const double x = -to[1], y = to[0];
  const double n = std::sqrt(w * w + x * x + y * y);
  return {w / n, x / n, y / n, 0};
}

std::string export_lights(const LightSet& set, LightFormat format, MitsubaFrame frame) {
  switch (format) {
    case LightFormat::Mitsuba:
      return mitsuba_lights(set, frame);
    case LightFormat::Blender:
      return blender_lights(set);
    case LightFormat::Usd:
      return usd_lights(set);
    case LightFormat::Gltf:
      return gltf_lights(set);
    case LightFormat::Answer:
      break;
  }
  throw std::logic_error("export_lights: json is the endpoint's own answer");
}

std::string light_format_content_type(LightFormat format) {
  switch (format) {
    case LightFormat::Mitsuba:
      return "application/xml";
    case LightFormat::Blender:
      return "text/x-python";
    case LightFormat::Usd:
      return "text/plain; charset=utf-8";
    case LightFormat::Gltf:
      return "model/gltf+json";
    case LightFormat::Answer:
      break;
  }
  return "application/json";
}

}  // namespace lp::api

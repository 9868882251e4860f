#include "api/sun_schema.hpp"

#include <cmath>

#include "api/sun_request.hpp"
#include "engine/core/constants.hpp"

namespace lp::api {
namespace {

void add_sun(Json& out, const Sun& s) {
  const Direction& d = s.axis;
  double phi = std::atan2(d[1], d[0]);
  if (phi < 0) phi += 2 * kPi;
  out["direction"] = d;
  out["theta"] = std::atan2(std::hypot(d[0], d[1]), d[2]);
  out["phi"] = phi;
  out["pixel"] = {s.pixel.x, s.pixel.y};
  out["angular_radius"] = s.angular_radius;
  out["solid_angle"] = s.solid_angle;
  out["color"] = s.color;
  out["irradiance"] = s.irradiance;
  out["share"] = s.share;
  out["contrast"] = std::isfinite(s.contrast) ? Json(s.contrast) : Json(nullptr);
  out["removed_radius"] = s.removed_radius;
  out["removed_pixels"] = s.removed_pixels;
  out["fill"] = s.fill;
}

}  // namespace

Json sun_json(const SunExtraction& e, const std::optional<std::string>& residual, bool cached) {
  Json out = {{"found", e.sun.has_value()}};
  if (e.sun)
    add_sun(out, *e.sun);
  else
    out["reason"] = e.reason;
  const Power none{};
  out["power"] = {{"map", e.map_power}, {"residual", e.residual_power}, {"sun", e.sun ? e.sun->power : none}};
  out["residual"] = residual ? Json(*residual) : Json(nullptr);
  out["parameters"] = sun_params_json(e.params);
  out["elapsed_ms"] = e.elapsed_ms;
  out["cached"] = cached;
  return out;
}

}  // namespace lp::api

#include "api/fresnel_schema.hpp"

#include <fmt/format.h>

namespace lp::api {
namespace {

Json channels_json(const Rgb64& v) {
  return {{"r", v[0]}, {"g", v[1]}, {"b", v[2]}};
}

template <typename Curve>
Json channel_curves_json(const ConductorTable& t, Curve curve) {
  return {{"r", curve(t.channels[0])}, {"g", curve(t.channels[1])}, {"b", curve(t.channels[2])}};
}

// Shortest text that reads back as the same double.
void append_row(std::string& out, std::initializer_list<double> values) {
  bool first = true;
  for (const double v : values) {
    if (!first) out += ',';
    out += fmt::format("{}", v);
    first = false;
  }
  out += '\n';
}

}  // namespace

Json fresnel_json(const DielectricTable& t) {
  return {{"kind", "dielectric"},
          {"eta_i", t.eta_i},
          {"eta_t", t.eta_t},
          {"angles_deg", t.angles_deg},
          {"rs", t.rs},
          {"rp", t.rp},
          {"unpolarized", t.unpolarized},
          {"schlick", t.schlick},
          {"r0", t.r0},
          {"brewster_deg", t.brewster_deg},
          {"critical_deg", t.critical_deg ? Json(*t.critical_deg) : Json(nullptr)},
          {"schlick_max_abs_error", t.schlick_max_abs_error},
          {"schlick_max_error_angle_deg", t.schlick_max_error_angle_deg}};
}

Json fresnel_json(const ConductorTable& t, const std::optional<std::string>& metal) {
  return {{"kind", "conductor"},
          {"metal", metal ? Json(*metal) : Json(nullptr)},
          {"wavelengths_nm", metal ? channels_json(kMetalWavelengthsNm) : Json(nullptr)},
          {"eta_i", t.eta_i},
          {"eta", channels_json(t.eta)},
          {"k", channels_json(t.k)},
          {"angles_deg", t.angles_deg},
          {"r", t.channels[0].unpolarized},
          {"g", t.channels[1].unpolarized},
          {"b", t.channels[2].unpolarized},
          {"rs", channel_curves_json(t, [](const ConductorCurves& c) { return c.rs; })},
          {"rp", channel_curves_json(t, [](const ConductorCurves& c) { return c.rp; })},
          {"r0", channels_json(t.r0)}};
}

std::string fresnel_csv(const DielectricTable& t) {
  std::string out = "angle_deg,rs,rp,unpolarized,schlick\n";
  for (size_t i = 0; i < t.angles_deg.size(); ++i)
    append_row(out, {t.angles_deg[i], t.rs[i], t.rp[i], t.unpolarized[i], t.schlick[i]});
  return out;
}

std::string fresnel_csv(const ConductorTable& t) {
  std::string out = "angle_deg,r,g,b,rs_r,rs_g,rs_b,rp_r,rp_g,rp_b\n";
  const auto& [r, g, b] = t.channels;
  for (size_t i = 0; i < t.angles_deg.size(); ++i)
    append_row(out, {t.angles_deg[i], r.unpolarized[i], g.unpolarized[i], b.unpolarized[i], r.rs[i], g.rs[i],
                     b.rs[i], r.rp[i], g.rp[i], b.rp[i]});
  return out;
}

}  // namespace lp::api

#include "api/sh_schema.hpp"

#include <nlohmann/json.hpp>

namespace lp::api {
namespace {

using Ordered = nlohmann::ordered_json;

Ordered coefficients(const ShCoefficients& c) {
  Ordered out = Ordered::array();
  for (int l = 0; l < c.bands; ++l)
    for (int m = -l; m <= l; ++m) {
      const ShRgb& v = c.rgb[size_t(sh_index(l, m))];
      out.push_back({{"l", l}, {"m", m}, {"rgb", {v[0], v[1], v[2]}}});
    }
  return out;
}

Ordered convention() {
  return {{"basis", "real spherical harmonics, orthonormal: the integral of Y_lm^2 over the sphere is 1"},
          {"condon_shortley_phase", false},
          {"frame",
           "z up; theta from +z, phi from +x toward +y; direction = (sin theta cos phi, sin theta sin "
           "phi, cos theta), as the lat-long map's pixels"},
          {"order", "l = 0, 1, ...; within a band m = -l .. l; index l (l + 1) + m"},
          {"band_1", "(Y_1,-1, Y_1,0, Y_1,1) = sqrt(3 / (4 pi)) (y, z, x)"},
          {"m_positive", "sqrt(2) K_lm cos(m phi) P_l^m(cos theta)"},
          {"m_negative", "sqrt(2) K_l|m| sin(|m| phi) P_l^|m|(cos theta)"},
          {"reconstruction", "f(w) = sum over l, m of c_lm Y_lm(w)"},
          {"quadrature",
           "every pixel a patch of constant radiance, Y_lm integrated over its area: the theta part "
           "K_lm P_l^m(cos theta) sin theta over the row's theta span by 8-point Gauss-Legendre (exact to "
           "rounding for these bands), the phi part in closed form, dphi sinc(m dphi / 2) times cos(m phi) "
           "or sin(m phi) at the column's centre; summed in double precision row by row"}};
}

Ordered window_json(const ShRequest& r) {
  return {{"name", enum_name(r.window)}, {"factors", sh_window_factors(r.window, r.bands)}};
}

}  // namespace

std::string sh_json(const ShCoefficients& full, const ShRequest& request, double elapsed_ms, bool cached) {
  const ShCoefficients radiance = sh_radiance(full, request);
  Ordered out = {{"bands", request.bands},
                 {"coefficient_count", sh_coefficient_count(request.bands)},
                 {"convention", convention()},
                 {"window", window_json(request)},
                 {"radiance", {{"quantity", "radiance L"}, {"coefficients", coefficients(radiance)}}}};
  if (request.irradiance) {
    const ShCoefficients e = sh_irradiance(radiance);
    const ShCoefficients lambertian = sh_lambertian(radiance);
    const std::string convolution = "clamped cosine (Ramamoorthi and Hanrahan 2001): E_lm = A_l L_lm";
    out["irradiance"] = {{"quantity", "irradiance E"},
                         {"includes_1_over_pi", false},
                         {"convolution", convolution},
                         {"band_factors", sh_cosine_lobe_factors(request.bands)},
                         {"coefficients", coefficients(e)}};
    out["lambertian"] = {{"quantity", "exitant radiance E / pi of a white Lambertian surface"},
                         {"includes_1_over_pi", true},
                         {"convolution", convolution + ", divided by pi"},
                         {"coefficients", coefficients(lambertian)}};
  }
  out["elapsed_ms"] = elapsed_ms;
  out["cached"] = cached;
  return out.dump();
}

}  // namespace lp::api

#include "engine/fresnel/schlick.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/fresnel/angles.hpp"
#include "engine/fresnel/dielectric.hpp"

namespace lp {

double schlick_r0(double eta_i, double eta_t) {
  const double r = (eta_i - eta_t) / (eta_i + eta_t);
  return r * r;
}

double fresnel_schlick(double cos_i, double eta_i, double eta_t) {
  double c = std::clamp(cos_i, 0.0, 1.0);
  if (eta_i > eta_t) {
    const std::optional<double> cos_t = transmitted_cos(c, eta_i, eta_t);
    if (!cos_t) return 1.0;
    c = *cos_t;
  }
  const double r0 = schlick_r0(eta_i, eta_t);
  const double m = 1.0 - c;
  return r0 + (1.0 - r0) * (m * m) * (m * m) * m;
}

SchlickMaxError schlick_max_error(double eta_i, double eta_t) {
  const auto error = [&](double deg) {
    const double c = cos_deg(deg);
    return std::abs(fresnel_schlick(c, eta_i, eta_t) -
                    fresnel_dielectric_polarized(c, eta_i, eta_t).reflectance());
  };

  constexpr int kScanSteps = 9000;  // every 0.01 degree
  constexpr double kScanStep = 90.0 / kScanSteps;
  SchlickMaxError best;
  int best_i = 0;
  for (int i = 0; i <= kScanSteps; ++i) {
    const double deg = i * kScanStep;
    const double e = error(deg);
    if (e > best.max_abs_error) {
      best = {e, deg};
      best_i = i;
    }
  }

  // The error is smooth and single-peaked within one scan step either side of the best point.
  constexpr double kInvPhi = 0.6180339887498949;  // 1 / golden ratio
  double lo = std::max(0, best_i - 1) * kScanStep;
  double hi = std::min(kScanSteps, best_i + 1) * kScanStep;
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double e1 = error(x1), e2 = error(x2);
  while (hi - lo > 1e-10) {
    if (e1 < e2) {
      lo = x1;
      x1 = x2;
      e1 = e2;
      x2 = lo + kInvPhi * (hi - lo);
      e2 = error(x2);
    } else {
      hi = x2;
      x2 = x1;
      e2 = e1;
      x1 = hi - kInvPhi * (hi - lo);
      e1 = error(x1);
    }
  }
  const double deg = 0.5 * (lo + hi);
  const double e = error(deg);
  if (e > best.max_abs_error) best = {e, deg};
  return best;
}

}  // namespace lp

#include "support/chi_square.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace lp::test {
namespace {

// P(a, x) by its power series; converges quickly for x < a + 1.
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by its continued fraction (modified Lentz); converges quickly for x >= a + 1.
double gamma_q_fraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  if (x <= 0) return 1.0;
  return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

ChiSquareResult chi_square_test(std::span<const double> observed, std::span<const double> expected,
                                double min_expected) {
  if (observed.size() != expected.size()) throw std::invalid_argument("observed and expected differ in size");
  ChiSquareResult r;
  double pooled_obs = 0, pooled_exp = 0;
  int cells = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < min_expected) {
      pooled_obs += observed[i];
      pooled_exp += expected[i];
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++cells;
  }
  if (pooled_exp > 0) {
    r.statistic += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
    ++cells;
  } else if (pooled_obs > 0) {
    r.statistic = INFINITY;  // samples where the pdf says none can fall
  }
  r.degrees_of_freedom = cells - 1;
  r.p_value =
      std::isfinite(r.statistic) ? regularized_gamma_q(0.5 * r.degrees_of_freedom, 0.5 * r.statistic) : 0.0;
  return r;
}

std::string ChiSquareResult::summary() const {
  return fmt::format("chi2 = {:.1f}, dof = {}, p = {:.4g}", statistic, degrees_of_freedom, p_value);
}

}  // namespace lp::test

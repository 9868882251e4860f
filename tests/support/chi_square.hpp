#pragma once
// Pearson's chi-square goodness-of-fit test, as Mitsuba tests its warps: observed counts against
// expected counts from the pdf, cells with expected < 5 pooled into one, p-value from the exact
// regularised incomplete gamma function.
#include <span>
#include <string>

namespace lp::test {

struct ChiSquareResult {
  double statistic = 0;
  int degrees_of_freedom = 0;
  double p_value = 0;
  std::string summary() const;
};

ChiSquareResult chi_square_test(std::span<const double> observed, std::span<const double> expected,
                                double min_expected = 5.0);

// Q(a, x) = Gamma(a, x) / Gamma(a): the upper tail, so chi-square p = Q(dof / 2, statistic / 2).
double regularized_gamma_q(double a, double x);

}  // namespace lp::test

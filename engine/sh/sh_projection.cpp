#include "engine/sh/sh_projection.hpp"

#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "engine/sh/gauss_legendre.hpp"
#include "engine/sh/row_harmonics.hpp"

namespace lp {
namespace {

// The theta part of Y_lm integrated over row y: the integral from theta_0 to theta_1 of
// K_lm P_l^m(cos theta) sin theta, by 8-point Gauss-Legendre (exact to rounding for these smooth
// polynomials over a row), at [sh_index(l, m)] for m >= 0.
ShBasis row_theta_integrals(int y, int height, int bands) {
  const auto& kNodes = kGaussLegendre8Nodes;
  const auto& kWeights = kGaussLegendre8Weights;
  const double t0 = kPi * y / height, t1 = kPi * (y + 1) / height;
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  ShBasis out{};
  for (size_t i = 0; i < kNodes.size(); ++i)
    for (const double sign : {-1.0, 1.0}) {
      const double theta = mid + sign * half * kNodes[i];
      const ShBasis p = sh_legendre(bands, std::cos(theta));
      for (int l = 0; l < bands; ++l)
        for (int m = 0; m <= l; ++m)
          out[size_t(sh_index(l, m))] +=
              kWeights[i] * half * std::sin(theta) * sh_normalisation(l, m) * p[sh_index(l, m)];
    }
  return out;
}

// The phi part of Y_lm integrated over one column of width dphi centred at phi: cos(m phi) (or
// sin(m phi)) times dphi sinc(m dphi / 2); this is the factor beside the centre's cosine and sine.
double column_phi_factor(int m, double dphi) {
  const double x = 0.5 * m * dphi;
  return m == 0 ? dphi : dphi * std::sin(x) / x;
}

// One row's contribution: the row sums S_m = sum_x L cos(m phi_x), T_m = sum_x L sin(m phi_x) times the
// integrals of each Y_lm's theta and phi parts over a pixel of the row, so that every pixel counts as a
// patch of constant radiance, integrated exactly. Rows are summed in order afterwards, so the result
// does not depend on the thread count.
std::vector<ShRgb> project_row(const Image& image, int y, int bands, const RowHarmonics& harmonics) {
  const auto sums = harmonics.sums(image.row(y));
  const double dphi = 2 * kPi / image.width();
  const ShBasis theta = row_theta_integrals(y, image.height(), bands);
  std::vector<ShRgb> out(size_t(sh_coefficient_count(bands)));
  for (int l = 0; l < bands; ++l)
    for (int m = 0; m <= l; ++m) {
      const double k =
          (m == 0 ? 1 : std::sqrt(2.0)) * theta[size_t(sh_index(l, m))] * column_phi_factor(m, dphi);
      for (int c = 0; c < 3; ++c) {
        out[size_t(sh_index(l, m))][c] = k * sums[size_t(RowHarmonics::cos_index(m))][c];
        if (m > 0) out[size_t(sh_index(l, -m))][c] = k * sums[size_t(RowHarmonics::sin_index(m))][c];
      }
    }
  return out;
}

}  // namespace

ShCoefficients ShCoefficients::truncated(int keep_bands) const {
  ShCoefficients out{keep_bands, rgb};
  out.rgb.resize(size_t(sh_coefficient_count(keep_bands)));
  return out;
}

ShRgb ShCoefficients::evaluate(double x, double y, double z) const {
  const ShBasis basis = sh_basis(bands, x, y, z);
  ShRgb out{};
  for (size_t i = 0; i < rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) out[c] += rgb[i][c] * basis[i];
  return out;
}

ShCoefficients project_sh(const Image& latlong, int bands) {
  const RowHarmonics harmonics(latlong.width(), bands);
  std::vector<std::vector<ShRgb>> rows(size_t(latlong.height()));
  tbb::parallel_for(0, latlong.height(),
                    [&](int y) { rows[size_t(y)] = project_row(latlong, y, bands, harmonics); });
  ShCoefficients out{bands, std::vector<ShRgb>(size_t(sh_coefficient_count(bands)))};
  for (const auto& row : rows)
    for (size_t i = 0; i < row.size(); ++i)
      for (int c = 0; c < 3; ++c) out.rgb[i][c] += row[i][c];
  return out;
}

std::shared_ptr<const ShProjection> sh_projection_cached(const EnvMap& map, bool* hit) {
  if (hit) *hit = true;
  const int64_t bytes = int64_t(sizeof(ShProjection)) + kMaxShCoefficients * int64_t(sizeof(ShRgb));
  return map.derived<ShProjection>("sh", bytes, [&] {
    if (hit) *hit = false;
    const auto start = std::chrono::steady_clock::now();
    ShProjection result{project_sh(map.image()), 0};
    result.elapsed_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return std::make_shared<const ShProjection>(std::move(result));
  });
}

std::vector<double> sh_window_factors(ShWindow window, int bands) {
  std::vector<double> f(static_cast<size_t>(bands), 1.0);
  for (int l = 1; l < bands; ++l) {
    const double t = double(l) / bands;
    if (window == ShWindow::Hann) f[size_t(l)] = 0.5 * (1 + std::cos(kPi * t));
    if (window == ShWindow::Lanczos) f[size_t(l)] = std::sin(kPi * t) / (kPi * t);
  }
  return f;
}

ShCoefficients scaled_by_band(const ShCoefficients& c, const std::vector<double>& factors) {
  ShCoefficients out = c;
  for (int l = 0; l < c.bands; ++l)
    for (int m = -l; m <= l; ++m)
      for (double& v : out.rgb[size_t(sh_index(l, m))]) v *= factors[size_t(l)];
  return out;
}

// 2 pi (-1)^(l/2 - 1) / ((l + 2)(l - 1)) * l! / (2^l ((l/2)!)^2) for even l >= 2; 0 for odd l > 1.
double sh_cosine_lobe_factor(int l) {
  if (l == 0) return kPi;
  if (l == 1) return 2 * kPi / 3;
  if (l % 2 == 1) return 0;
  double ratio = 1;  // l! / (2^l ((l/2)!)^2)
  for (int k = 1; k <= l / 2; ++k) ratio *= double(l / 2 + k) / (4.0 * k);
  const double sign = (l / 2 - 1) % 2 == 0 ? 1 : -1;
  return 2 * kPi * sign / ((l + 2) * (l - 1)) * ratio;
}

std::vector<double> sh_cosine_lobe_factors(int bands) {
  std::vector<double> f(static_cast<size_t>(bands));
  for (int l = 0; l < bands; ++l) f[size_t(l)] = sh_cosine_lobe_factor(l);
  return f;
}

ShCoefficients sh_irradiance(const ShCoefficients& radiance) {
  return scaled_by_band(radiance, sh_cosine_lobe_factors(radiance.bands));
}

ShCoefficients sh_lambertian(const ShCoefficients& radiance) {
  std::vector<double> factors = sh_cosine_lobe_factors(radiance.bands);
  for (double& f : factors) f /= kPi;
  return scaled_by_band(radiance, factors);
}

}  // namespace lp

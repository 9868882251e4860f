#include "engine/sh/sh_irradiance_form.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/core/constants.hpp"

namespace lp {

ShIrradianceForm::ShIrradianceForm(const ShCoefficients& irradiance) {
  if (irradiance.bands < 3) throw std::invalid_argument("the irradiance form needs 3 bands");
  const auto e = [&](int l, int m) {
    const ShRgb& c = irradiance.rgb[size_t(sh_index(l, m))];
    return (c[0] + c[1] + c[2]) / 3;
  };
  // The basis of sh_basis.hpp written out for bands 0 to 2.
  const double k0 = 0.5 * std::sqrt(1 / kPi), k1 = std::sqrt(3 / (4 * kPi));
  const double k2 = 0.5 * std::sqrt(15 / kPi), k20 = 0.25 * std::sqrt(5 / kPi),
               k22 = 0.25 * std::sqrt(15 / kPi);
  c_ = float(k0 * e(0, 0) - k20 * e(2, 0));
  b_ = {float(k1 * e(1, 1)), float(k1 * e(1, -1)), float(k1 * e(1, 0))};
  xx_ = float(k22 * e(2, 2));
  yy_ = float(-k22 * e(2, 2));
  zz_ = float(3 * k20 * e(2, 0));
  xy_ = float(k2 * e(2, -2));
  yz_ = float(k2 * e(2, -1));
  xz_ = float(k2 * e(2, 1));
}

}  // namespace lp

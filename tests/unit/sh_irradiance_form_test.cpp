// The quadratic form of band-3 irradiance against the SH reconstruction it replaces.
#include "engine/sh/sh_irradiance_form.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/envmap/envmap.hpp"
#include "support/real_maps.hpp"

namespace lp {
namespace {

TEST(ShIrradianceForm, EqualsTheBand3ReconstructionOfIrradiance) {
  for (const char* file : {"forest.exr", "sunrise.exr", "studio.exr"}) {
    const ShCoefficients irradiance =
        sh_irradiance(sh_projection_cached(*test::real_map(file))->radiance.truncated(3));
    const ShIrradianceForm form(irradiance);
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss;
    for (int i = 0; i < 200; ++i) {
      double x = gauss(rng), y = gauss(rng), z = gauss(rng);
      const double r = std::sqrt(x * x + y * y + z * z);
      x /= r, y /= r, z /= r;
      const ShRgb e = irradiance.evaluate(x, y, z);
      const double expected = (e[0] + e[1] + e[2]) / 3;
      EXPECT_NEAR(form(Vec3{float(x), float(y), float(z)}), expected, 1e-5 * std::abs(irradiance.rgb[0][0]))
          << file << " at (" << x << ", " << y << ", " << z << ")";
    }
  }
}

TEST(ShIrradianceForm, NeedsThreeBands) {
  ShCoefficients two;
  two.bands = 2;
  two.rgb.resize(4);
  EXPECT_THROW(ShIrradianceForm{two}, std::invalid_argument);
}

}  // namespace
}  // namespace lp

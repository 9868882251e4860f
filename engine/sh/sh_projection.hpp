#pragma once
// Projection of a lat-long map onto the real SH basis (sh_basis.hpp), exact over the pixels: each pixel
// is a patch of constant radiance, and each Y_lm is integrated over the patch (its phi part in closed
// form, its theta part by Gauss-Legendre to rounding), so a constant map has no coefficient beyond L00. The
// per-map result holds all kMaxShBands bands; fewer bands are its prefix (a coefficient does not depend on
// how many follow).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/sh/sh_basis.hpp"

namespace lp {

class Image;
class EnvMap;

using ShRgb = std::array<double, 3>;

struct ShCoefficients {
  int bands = 0;
  std::vector<ShRgb> rgb;  // sh_coefficient_count(bands) entries, index l (l + 1) + m

  ShCoefficients truncated(int keep_bands) const;
  // The reconstruction sum_lm c_lm Y_lm at the unit direction (x, y, z).
  ShRgb evaluate(double x, double y, double z) const;
};

ShCoefficients project_sh(const Image& latlong, int bands = kMaxShBands);

// project_sh(map.image()) cached on the map ("sh"), with the time it took; `hit` (optional) tells
// whether the result came from the cache.
struct ShProjection {
  ShCoefficients radiance;
  double elapsed_ms = 0;
};
std::shared_ptr<const ShProjection> sh_projection_cached(const EnvMap& map, bool* hit = nullptr);

// Ringing windows (Sloan, "Stupid Spherical Harmonics Tricks", 2008) over the `bands` kept, a factor per
// band l: none 1; hann (1 + cos(pi l / bands)) / 2; lanczos sinc(l / bands).
enum class ShWindow { None, Hann, Lanczos };
constexpr auto enum_entries(ShWindow) {
  return std::to_array<EnumEntry<ShWindow>>(
      {{ShWindow::None, "none"}, {ShWindow::Hann, "hann"}, {ShWindow::Lanczos, "lanczos"}});
}
std::vector<double> sh_window_factors(ShWindow window, int bands);
ShCoefficients scaled_by_band(const ShCoefficients& c, const std::vector<double>& factors);

// The clamped-cosine convolution of Ramamoorthi and Hanrahan (2001): A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4, A_3 = 0, A_4 = -pi / 24. Irradiance E_lm = A_l L_lm; a white Lambertian surface
// reflects E / pi.
double sh_cosine_lobe_factor(int l);
std::vector<double> sh_cosine_lobe_factors(int bands);
ShCoefficients sh_irradiance(const ShCoefficients& radiance);  // E_lm = A_l L_lm
ShCoefficients sh_lambertian(const ShCoefficients& radiance);  // E_lm / pi

}  // namespace lp

#pragma once
// GET /envmaps/{id}/sh and GET /envmaps/{id}/sh.png queries.
#include "api/params.hpp"
#include "engine/image/image_io.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::api {

// What sh.png shows: the radiance reconstruction, or the radiance E / pi a white Lambertian surface
// facing each direction reflects (the irradiance in the map's units).
enum class ShQuantity { Radiance, Lambertian };
constexpr auto enum_entries(ShQuantity) {
  return std::to_array<EnumEntry<ShQuantity>>(
      {{ShQuantity::Radiance, "radiance"}, {ShQuantity::Lambertian, "lambertian"}});
}

inline constexpr int kDefaultShBands = 3;
// sh.png is as wide as the map up to this many pixels, or `width` in kShImageWidth; twice as wide as high.
inline constexpr int kDefaultShImageMaxWidth = 1024;
inline constexpr Range<int64_t> kShImageWidth{2, 4096};

struct ShRequest {
  int bands = kDefaultShBands;
  bool irradiance = true;
  ShWindow window = ShWindow::None;
};

// bands in [1, 5] (default 3), irradiance=true|false (default true), window=none|hann|lanczos.
ShRequest parse_sh_query(const Query& q);

struct ShImageRequest {
  ShRequest sh;
  ShQuantity quantity = ShQuantity::Radiance;
  std::optional<int> width;
  ToneMap tone;
};

// bands, window (as above), quantity=radiance|lambertian, width, exposure, gamma.
ShImageRequest parse_sh_image_query(const Query& q);

// The radiance coefficients `request` asks for, from the map's full projection: truncated and windowed.
ShCoefficients sh_radiance(const ShCoefficients& full, const ShRequest& request);

}  // namespace lp::api

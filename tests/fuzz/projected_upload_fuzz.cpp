// POST /api/v1/envmaps?projection=...: any bytes decoded as an image file, the first byte picking the
// projection the file is said to be in; its shape checked against the projection, its bad pixels clamped
// and the image converted to a lat-long map, as the server loads such an upload (every converted value
// must be finite and not negative). The decoded pixels as they came, NaN, Inf and negatives included,
// are resampled into another projection too.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "api/projection_params.hpp"
#include "decoder_fuzz.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/invalid_pixels.hpp"
#include "engine/projection/reproject.hpp"
#include "fuzz_input.hpp"

namespace {

// Small maps keep every run short: a lat-long map of at most 90 x 45 pixels (a cross of faces up to 22, a
// square up to 45).
constexpr int64_t kMaxConvertedPixels = int64_t{1} << 12;

void check_converted(const lp::Image& latlong) {
  for (const float v : latlong.data())
    if (!std::isfinite(v) || v < 0) {
      std::fprintf(stderr, "converted value %g\n", double(v));
      std::abort();
    }
}

void load(lp::Projection projection, std::span<const uint8_t> bytes, const lp::ImageLimits& limits) {
  lp::Image image = lp::read_image(bytes, limits).image;
  const auto projections = enum_entries(lp::Projection{});
  const lp::Projection other = projections[(size_t(projection) + 1) % projections.size()].value;
  if (lp::projection_size(projection, image.width(), image.height()))
    lp::reproject(image, projection, other, 3);  // the raw pixels; 3: the folds cross texels' middles
  int width = 0;
  try {
    width = lp::api::input_latlong_width(projection, image.width(), image.height(), kMaxConvertedPixels);
  } catch (const lp::api::ApiError& e) {
    lp::fuzz::check_rejection(e);
    return;
  }
  if (projection == lp::Projection::LatLong) return;
  const lp::InvalidPixelReport fixed = lp::sanitize_radiance(image, lp::InvalidPixelPolicy::Clamp);
  lp::Image latlong = lp::reproject(image, projection, lp::Projection::LatLong, width);
  check_converted(latlong);
  const lp::EnvMap map(std::move(latlong), lp::InvalidPixelPolicy::Reject, fixed);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const auto projections = enum_entries(lp::Projection{});
  const lp::Projection projection = projections[data[0] % projections.size()].value;
  return lp::fuzz::decode(data + 1, size - 1,
                          [projection](std::span<const uint8_t> bytes, const lp::ImageLimits& limits) {
                            load(projection, bytes, limits);
                          });
}

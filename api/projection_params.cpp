#include "api/projection_params.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "api/api_error.hpp"

namespace lp::api {
namespace {

int64_t pixels(Projection projection, int64_t size) {
  const ImageShape one = projection_shape(projection, 1);
  return one.width * one.height * size * size;
}

}  // namespace

ProjectionParams parse_projection_params(const Query& q) {
  ProjectionParams p;
  p.projection = query_enum(q, "projection", Projection::LatLong);
  const Range<int64_t> range = limits::kProjectionSize;
  if (query_string(q, "size")) {
    if (p.projection == Projection::LatLong)
      throw invalid_field("size",
                          "applies to the projections cube, cross, octahedral and equal-area; "
                          "latlong is the map as it is held");
    p.size = int(query_int(q, "size", range.min, range.min, range.max));
  }
  if (query_string(q, "face")) {
    if (p.projection != Projection::Cube) throw invalid_field("face", "applies to projection=cube only");
    p.face = query_enum(q, "face", CubeFace::PosX);
  }
  return p;
}

int projection_image_size(const ProjectionParams& params, int latlong_width, int64_t max_pixels) {
  const Projection p = params.projection;
  if (params.size) {
    if (pixels(p, *params.size) > max_pixels)
      throw invalid_field("size",
                          fmt::format("a {} of size {} has {} pixels, over the largest image of {} "
                                      "(--max-pixels)",
                                      enum_name(p), *params.size, pixels(p, *params.size), max_pixels));
    return *params.size;
  }
  int64_t size = std::clamp<int64_t>(equivalent_size(p, latlong_width), limits::kProjectionSize.min,
                                     limits::kProjectionSize.max);
  while (size > limits::kProjectionSize.min && pixels(p, size) > max_pixels) --size;
  return int(size);
}

Projection parse_input_projection(const Query& q, const std::string& name) {
  return query_enum(q, name, Projection::LatLong);
}

int input_latlong_width(Projection projection, int width, int height, int64_t max_pixels,
                        const std::string& field) {
  const std::optional<int> size = projection_size(projection, width, height);
  if (!size)
    throw invalid_field(field,
                        fmt::format("the image must be {} for projection {}, got {} x {}",
                                    projection_shape_rule(projection), enum_name(projection), width, height));
  const ImageShape latlong =
      projection_shape(Projection::LatLong, equivalent_latlong_width(projection, *size));
  if (int64_t(latlong.width) * latlong.height > max_pixels)
    throw ApiError(
        ErrorCode::TooLarge,
        fmt::format("converted from {}, the lat-long map would have {} x {} pixels, over the largest "
                    "map of {} (--max-pixels)",
                    enum_name(projection), latlong.width, latlong.height, max_pixels));
  return latlong.width;
}

}  // namespace lp::api

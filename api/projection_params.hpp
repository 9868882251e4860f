#pragma once
// The projection query parameters: of GET /envmaps/{id}/image, `projection` (latlong, the default, gives
// the map as held), `size` and, for a cube, `face`; of POST /envmaps, `projection`, how the file's pixels
// are laid out (converted to lat-long on load).
#include <optional>

#include "api/params.hpp"
#include "engine/core/limits.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/projection.hpp"

namespace lp::api {

struct ProjectionParams {
  Projection projection = Projection::LatLong;
  std::optional<int> size;       // in limits::kProjectionSize; only for the projections other than latlong
  std::optional<CubeFace> face;  // only for cube: one face instead of the strip of six
};

ProjectionParams parse_projection_params(const Query& q);

// The size of the image asked for a map `latlong_width` wide: `size`, else equivalent_size() (a quarter
// of the width for a cube or cross, half for a square map), made smaller if need be so the image (all of
// it: the strip of six faces, the cross of 4 x 3 cells) has at most `max_pixels` pixels. A size given
// whose image has more is a 400 naming `size`.
int projection_image_size(const ProjectionParams& params, int latlong_width, int64_t max_pixels);

// The layout of an image file being loaded, from the query parameter `name` (default latlong).
Projection parse_input_projection(const Query& q, const std::string& name = "projection");

// The width of the lat-long map an image of width x height in `projection` becomes (equivalent_latlong_width;
// its height is half of it): 400 naming `field` if the shape does not fit the projection, 413 if the
// lat-long map would have more than `max_pixels` pixels.
int input_latlong_width(Projection projection, int width, int height, int64_t max_pixels,
                        const std::string& field = "projection");

}  // namespace lp::api

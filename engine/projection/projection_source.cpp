#include "engine/projection/projection_source.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/projection/source_charts.hpp"

namespace lp {

bool ProjectionSource::needs_split(Vec3d a, Vec3d b) const {
  static const double cos_max = std::cos(kMaxSideRadians);
  return dot(a, b) < cos_max;
}

std::unique_ptr<const ProjectionSource> make_projection_source(const Image& image, Projection projection) {
  if (!projection_size(projection, image.width(), image.height()))
    throw Error(ErrorKind::InvalidArgument, std::string("the image must be ") +
                                                projection_shape_rule(projection) + " for projection " +
                                                enum_name(projection));
  switch (projection) {
    case Projection::LatLong:
      return make_latlong_source(image);
    case Projection::Cube:
    case Projection::Cross:
      return make_cube_source(image, projection);
    case Projection::Octahedral:
    case Projection::EqualArea:
      return make_square_source(image, projection);
  }
  throw Error(ErrorKind::InvalidArgument, "unknown projection");
}

}  // namespace lp

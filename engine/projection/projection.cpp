#include "engine/projection/projection.hpp"

#include <algorithm>

namespace lp {

ImageShape projection_shape(Projection projection, int size) {
  switch (projection) {
    case Projection::LatLong:
      return {size, std::max(1, size / 2)};
    case Projection::Cube:
      return {6 * size, size};
    case Projection::Cross:
      return {4 * size, 3 * size};
    case Projection::Octahedral:
    case Projection::EqualArea:
      return {size, size};
  }
  return {};
}

std::optional<int> projection_size(Projection projection, int width, int height) {
  if (width < 1 || height < 1) return std::nullopt;
  int size = width;
  if (projection == Projection::Cube) size = width / 6;
  if (projection == Projection::Cross) size = width / 4;
  if (projection != Projection::LatLong) {
    const ImageShape shape = projection_shape(projection, size);
    if (size < 1 || shape.width != width || shape.height != height) return std::nullopt;
  }
  return size;
}

const char* projection_shape_rule(Projection projection) {
  switch (projection) {
    case Projection::LatLong:
      return "any width x height";
    case Projection::Cube:
      return "6:1 (6N x N pixels, the faces side by side)";
    case Projection::Cross:
      return "4:3 (4N x 3N pixels)";
    case Projection::Octahedral:
    case Projection::EqualArea:
      return "square (N x N pixels)";
  }
  return "";
}

int equivalent_size(Projection projection, int latlong_width) {
  switch (projection) {
    case Projection::Cube:
    case Projection::Cross:
      return std::max(1, latlong_width / 4);
    case Projection::Octahedral:
    case Projection::EqualArea:
      return std::max(1, latlong_width / 2);
    case Projection::LatLong:
      break;
  }
  return latlong_width;
}

int equivalent_latlong_width(Projection projection, int size) {
  switch (projection) {
    case Projection::Cube:
    case Projection::Cross:
      return 4 * size;
    case Projection::Octahedral:
    case Projection::EqualArea:
      return 2 * size;
    case Projection::LatLong:
      break;
  }
  return size;
}

}  // namespace lp

#include "engine/projection/projection_texels.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/constants.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/equal_area.hpp"
#include "engine/projection/octahedral.hpp"
#include "engine/projection/target_panels.hpp"

namespace lp {
namespace {

int cell(double coordinate, int cells) {  // coordinate in [-1, 1]
  return std::clamp(int(std::floor((coordinate + 1) / 2 * cells)), 0, cells - 1);
}

Point2d square_centre(int x, int y, int size) {
  return {square_coordinate(x + 0.5, size), square_coordinate(y + 0.5, size)};
}

}  // namespace

Vec3d texel_centre_direction(Projection projection, ImageShape shape, int x, int y) {
  switch (projection) {
    case Projection::LatLong: {
      const double theta = kPi * (y + 0.5) / shape.height, phi = 2 * kPi * (x + 0.5) / shape.width;
      return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    }
    case Projection::Cube:
    case Projection::Cross: {
      const int size = shape.height / (projection == Projection::Cube ? 1 : 3);
      const auto t = cube_layout_texel(projection, size, x, y);
      return t ? normalize(cube_face_direction(t->face, square_centre(t->i, t->j, size))) : Vec3d{};
    }
    case Projection::Octahedral:
      return octahedral::direction(square_centre(x, y, shape.width));
    case Projection::EqualArea:
      return equal_area::direction(square_centre(x, y, shape.width));
  }
  return {};
}

Pixel texel_containing(Projection projection, ImageShape shape, Vec3d d) {
  switch (projection) {
    case Projection::LatLong: {
      double phi = std::atan2(d.y, d.x);
      if (phi < 0) phi += 2 * kPi;
      const double theta = std::atan2(std::hypot(d.x, d.y), d.z);
      return {std::clamp(int(phi / (2 * kPi) * shape.width), 0, shape.width - 1),
              std::clamp(int(theta / kPi * shape.height), 0, shape.height - 1)};
    }
    case Projection::Cube:
    case Projection::Cross: {
      const int size = shape.height / (projection == Projection::Cube ? 1 : 3);
      const CubeFacePoint p = cube_face_point(d);
      return cube_layout_pixel(projection, size, {p.face, cell(p.ab.x, size), cell(p.ab.y, size)});
    }
    case Projection::Octahedral:
    case Projection::EqualArea: {
      const Point2d uv = projection == Projection::Octahedral ? octahedral::square(d) : equal_area::square(d);
      return {cell(uv.x, shape.width), cell(uv.y, shape.width)};
    }
  }
  return {};
}

double texel_solid_angle(Projection projection, ImageShape shape, int x, int y) {
  switch (projection) {
    case Projection::LatLong:
      return latlong::pixel_solid_angle(y, shape.width, shape.height);
    case Projection::Cube:
    case Projection::Cross: {
      const int size = shape.height / (projection == Projection::Cube ? 1 : 3);
      const auto t = cube_layout_texel(projection, size, x, y);
      return t ? cube_texel_solid_angle(size, t->i, t->j) : 0.0;
    }
    case Projection::Octahedral: {
      thread_local SphericalPolygon outline;
      texel_outline(projection, shape.width, x, y, NoEdgeSplits(), outline);
      return std::abs(spherical_polygon_area(outline));
    }
    case Projection::EqualArea:
      return 4 * kPi / (double(shape.width) * shape.width);
  }
  return 0;
}

Rgb projected_power(const Image& image, Projection projection) {
  const ImageShape shape{image.width(), image.height()};
  std::vector<Vec3d> rows(size_t(image.height()));
  tbb::parallel_for(0, image.height(), [&](int y) {
    Vec3d sum;
    for (int x = 0; x < image.width(); ++x) {
      const double omega = texel_solid_angle(projection, shape, x, y);
      const Rgb c = image.at(x, y);
      sum = sum + Vec3d{c.x * omega, c.y * omega, c.z * omega};
    }
    rows[size_t(y)] = sum;
  });
  Vec3d total;
  for (const Vec3d& r : rows) total = total + r;  // in row order: the same sum on any thread count
  return to_float(total);
}

}  // namespace lp

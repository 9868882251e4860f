#include "engine/projection/projection_cache.hpp"

#include "engine/projection/reproject.hpp"

namespace lp {

std::shared_ptr<const Image> projection_cached(const EnvMap& map, Projection projection, int size) {
  if (projection == Projection::Cross) projection = Projection::Cube;
  const ImageShape shape = projection_shape(projection, size);
  const std::string key = std::string("projection:") + enum_name(projection) + ":" + std::to_string(size);
  return map.derived<Image>(key, EnvMap::image_bytes(shape.width, shape.height), [&] {
    return std::make_shared<const Image>(reproject(map.image(), Projection::LatLong, projection, size));
  });
}

}  // namespace lp
